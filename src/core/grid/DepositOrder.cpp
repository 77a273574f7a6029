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
    // The keys once (a sort compares each parcel ~log N times)
    std::vector<std::pair<Key, DepositEntry>> keyed;
    keyed.reserve(own.size() + copies.size());
    for (std::size_t i = 0; i < own.size(); ++i)
    {
        keyed.push_back({keyOf(own[i]), DepositEntry{false, i}});
    }
    for (std::size_t i = 0; i < copies.size(); ++i)
    {
        keyed.push_back({keyOf(copies[i]), DepositEntry{true, i}});
    }
    std::sort(keyed.begin(), keyed.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<DepositEntry> order;
    order.reserve(keyed.size());
    for (const auto& entry : keyed)
    {
        order.push_back(entry.second);
    }
    return order;
}

} // namespace dropletFiber
