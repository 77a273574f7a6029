// LevelTable: sparse values on the spread levels' nodes, summed per key (LevelTable.hpp).
#include "grid/LevelTable.hpp"

#include <algorithm>
#include <utility>
#include <stdexcept>
#include <string>

namespace dropletFiber
{

const double* LevelTable::find(LevelKey key) const
{
    const auto at = std::lower_bound(keys.begin(), keys.end(), key);
    if (at == keys.end() || *at != key)
    {
        return nullptr;
    }
    return values.data() + static_cast<std::size_t>(at - keys.begin()) * static_cast<std::size_t>(width);
}

void LevelTerms::add(LevelKey key, const double* values)
{
    keys_.push_back(key);
    values_.insert(values_.end(), values, values + width_);
}

void LevelTerms::add(const LevelTable& table)
{
    if (table.width != width_)
    {
        throw std::invalid_argument("LevelTerms: a table of width " + std::to_string(table.width)
                                    + " added to terms of width " + std::to_string(width_));
    }
    for (std::size_t i = 0; i < table.keys.size(); ++i)
    {
        add(table.keys[i], table.values.data() + i * static_cast<std::size_t>(width_));
    }
}

LevelTable LevelTerms::summed() const
{
    // (key, position) pairs: sorted by key, then by the order added
    std::vector<std::pair<LevelKey, std::size_t>> order(keys_.size());
    for (std::size_t i = 0; i < keys_.size(); ++i)
    {
        order[i] = {keys_[i], i};
    }
    std::sort(order.begin(), order.end());
    LevelTable table;
    table.width = width_;
    const auto w = static_cast<std::size_t>(width_);
    table.keys.reserve(order.size());
    table.values.reserve(order.size() * w);
    for (const auto& [key, i] : order)
    {
        if (table.keys.empty() || table.keys.back() != key)
        {
            table.keys.push_back(key);
            table.values.insert(table.values.end(), values_.begin() + static_cast<std::ptrdiff_t>(i * w),
                                values_.begin() + static_cast<std::ptrdiff_t>((i + 1) * w));
            continue;
        }
        double* sum = table.values.data() + table.values.size() - w;
        for (std::size_t c = 0; c < w; ++c)
        {
            sum[c] += values_[i * w + c];
        }
    }
    return table;
}

} // namespace dropletFiber
