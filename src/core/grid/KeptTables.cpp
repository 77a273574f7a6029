#include "grid/KeptTables.hpp"

#include <algorithm>
#include <cstring>

namespace dropletFiber
{

KeptTables::Key::Key(const Eigen::Vector3d& start, const Eigen::Vector3d& displacement, double diameter,
                     double nParticle)
    : values{{start[0], start[1], start[2], displacement[0], displacement[1], displacement[2], diameter,
              nParticle}}
{
}

bool KeptTables::Key::operator==(const Key& other) const
{
    // Bitwise: the same bits give the same tables (== would also match 0.0 with -0.0)
    return std::memcmp(values.data(), other.values.data(), sizeof(values)) == 0;
}

std::uint64_t KeptTables::Key::hash() const
{
    // FNV-1a over the values' bits
    std::uint64_t h = 14695981039346656037ULL;
    for (const double v : values)
    {
        std::uint64_t bits = 0;
        std::memcpy(&bits, &v, sizeof bits);
        for (int b = 0; b < 8; ++b)
        {
            h ^= (bits >> (8 * b)) & 0xffU;
            h *= 1099511628211ULL;
        }
    }
    return h;
}

void KeptTables::keep(const Key& key, const SeparableWeight& weights, double omegaSum, const IndexBox& box)
{
    const SeparableTables tables = weights.tables();
    Entry entry;
    entry.key = key;
    entry.box = box;
    entry.omegaSum = omegaSum;
    entry.points = tables.points;
    entry.lanes = tables.lanes;
    entry.length = tables.length;
    entry.offset = values_.size();
    values_.resize(values_.size() + weights.tableValues());
    weights.copyTables(values_.data() + entry.offset);
    entries_.push_back(entry);
    indexed_ = false;
}

const KeptTables::Entry* KeptTables::find(const Key& key) const
{
    if (entries_.empty())
    {
        return nullptr;
    }
    if (!indexed_)
    {
        index_.clear();
        for (std::size_t e = 0; e < entries_.size(); ++e)
        {
            index_.emplace_back(entries_[e].key.hash(), e);
        }
        std::sort(index_.begin(), index_.end());
        indexed_ = true;
    }
    const std::uint64_t h = key.hash();
    auto at = std::lower_bound(index_.begin(), index_.end(), std::make_pair(h, std::size_t{0}));
    for (; at != index_.end() && at->first == h; ++at)
    {
        if (entries_[at->second].key == key)
        {
            ++found_;
            return &entries_[at->second];
        }
    }
    return nullptr;
}

SeparableTables KeptTables::tables(const Entry& entry) const
{
    return SeparableTables::inCompactCopy(values_.data() + entry.offset, entry.points, entry.lanes,
                                          entry.length);
}

void KeptTables::clear()
{
    entries_.clear();
    values_.clear();
    index_.clear();
    indexed_ = true;
    found_ = 0;
}

std::size_t KeptTables::bytes() const
{
    return values_.size() * sizeof(double) + entries_.size() * (sizeof(Entry) + sizeof(index_[0]));
}

} // namespace dropletFiber
