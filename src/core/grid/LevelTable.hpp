// LevelTable: values on the nodes of the spread levels (SpreadLevel.hpp, docs/model.md sec.
// 12, P53), sparse: only the level nodes that computed fibers reach in a step. A key names
// the level and the node (its flat index on the level's lattice); each key holds `width`
// values. Terms are added in any order (LevelTerms) and summed per key in key order and,
// within a key, in the order added: the same sums for the same terms in the same order.
// The keys are exact in a double (node < 2^47), so a table travels in a list of scalars.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace dropletFiber
{

using LevelKey = std::uint64_t;

inline LevelKey levelKey(int level, std::size_t node)
{
    return (static_cast<LevelKey>(node) << 6) | static_cast<LevelKey>(level);
}
inline int levelOfKey(LevelKey key)
{
    return static_cast<int>(key & 63u);
}
inline std::size_t nodeOfKey(LevelKey key)
{
    return static_cast<std::size_t>(key >> 6);
}

// The largest level count a key holds.
constexpr int maxLevels = 64;

struct LevelTable
{
    int width = 1;
    std::vector<LevelKey> keys; // ascending, unique
    std::vector<double> values; // width per key

    std::size_t size() const { return keys.size(); }
    // The key's values, nullptr where the table has none.
    const double* find(LevelKey key) const;
    // Column `column` of the key's values, 0 where the table has none.
    double value(LevelKey key, int column) const
    {
        const double* v = find(key);
        return v != nullptr ? v[column] : 0.0;
    }
};

class LevelTerms
{
public:
    explicit LevelTerms(int width = 1) : width_(width) {}
    int width() const { return width_; }
    // One term of `width` values at key.
    void add(LevelKey key, const double* values);
    void add(LevelKey key, double value) { add(key, &value); }
    // The terms of a table (each key one term).
    void add(const LevelTable& table);
    bool empty() const { return keys_.empty(); }
    void clear()
    {
        keys_.clear();
        values_.clear();
    }
    // Per key the sum of its terms, keys ascending, each key's terms in the order added.
    LevelTable summed() const;

private:
    int width_;
    std::vector<LevelKey> keys_;
    std::vector<double> values_;
};

} // namespace dropletFiber
