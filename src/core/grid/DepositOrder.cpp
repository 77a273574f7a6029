#include "grid/DepositOrder.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>

namespace dropletFiber
{

namespace
{
using Key = std::array<std::uint64_t, parcelValueCount>;

Key keyOf(const Parcel& parcel)
{
    double values[parcelValueCount];
    writeParcelValues(parcel, values);
    Key key;
    std::memcpy(key.data(), values, sizeof values);
    return key;
}
} // namespace

bool depositsBefore(const Parcel& a, const Parcel& b)
{
    return keyOf(a) < keyOf(b);
}

std::vector<DepositEntry> depositOrder(const std::vector<Parcel>& own, const std::vector<Parcel>& copies)
{
    // Sorted by the first key word (x's bits) with the entry's place, 16 bytes each: the
    // whole keys are compared only where the first words tie
    const std::size_t ownCount = own.size();
    const auto parcel = [&](std::size_t place) -> const Parcel&
    { return place < ownCount ? own[place] : copies[place - ownCount]; };
    std::vector<std::pair<std::uint64_t, std::size_t>> keyed(ownCount + copies.size());
    for (std::size_t place = 0; place < keyed.size(); ++place)
    {
        keyed[place] = {keyOf(parcel(place))[0], place};
    }
    std::sort(keyed.begin(), keyed.end(),
              [&](const auto& a, const auto& b) {
                  return a.first != b.first ? a.first < b.first
                                            : keyOf(parcel(a.second)) < keyOf(parcel(b.second));
              });
    std::vector<DepositEntry> order(keyed.size());
    for (std::size_t i = 0; i < keyed.size(); ++i)
    {
        const std::size_t place = keyed[i].second;
        order[i] = place < ownCount ? DepositEntry{false, place} : DepositEntry{true, place - ownCount};
    }
    return order;
}

} // namespace dropletFiber
