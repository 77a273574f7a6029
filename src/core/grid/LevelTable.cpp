// LevelTable: sparse values on the spread levels' nodes, summed per key (LevelTable.hpp).
#include "grid/LevelTable.hpp"

#include <algorithm>
#include <numeric>
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
    std::vector<std::size_t> order(keys_.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [this](std::size_t a, std::size_t b) { return keys_[a] < keys_[b]; });
    LevelTable table;
    table.width = width_;
    const auto w = static_cast<std::size_t>(width_);
    for (const std::size_t i : order)
    {
        if (table.keys.empty() || table.keys.back() != keys_[i])
        {
            table.keys.push_back(keys_[i]);
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
