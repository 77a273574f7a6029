#include "grid/WindowTransfer.hpp"

#include <stdexcept>
#include <string>

namespace dropletFiber
{

namespace
{

constexpr std::size_t blockHeader = windowStateHeaderSize + 6;

[[noreturn]] void fail(const std::string& what)
{
    throw std::invalid_argument("joining window parts: " + what);
}

IndexBox boxAt(const std::vector<std::int64_t>& c, std::size_t at)
{
    IndexBox box;
    for (int d = 0; d < 3; ++d)
    {
        box.lo[d] = static_cast<int>(c[at + static_cast<std::size_t>(d)]);
        box.hi[d] = static_cast<int>(c[at + 3 + static_cast<std::size_t>(d)]);
    }
    return box.empty() ? IndexBox{} : box;
}

void appendBox(std::vector<std::int64_t>& c, const IndexBox& b)
{
    c.insert(c.end(), {b.lo[0], b.lo[1], b.lo[2], b.hi[0], b.hi[1], b.hi[2]});
}

} // namespace

void checkWindowParts(const std::vector<WindowState>& parts, const IndexBox& block)
{
    if (parts.empty())
    {
        fail("no parts");
    }
    const std::vector<std::int64_t>& first = parts.front().counters;
    std::size_t nodes = 0;
    for (std::size_t p = 0; p < parts.size(); ++p)
    {
        const std::vector<std::int64_t>& c = parts[p].counters;
        if (c.size() < blockHeader || c[0] != first[0]
            || !std::equal(c.begin(), c.begin() + windowStateHeaderSize, first.begin()))
        {
            fail("part " + std::to_string(p) + " is of another grid or window");
        }
        if (c.size() != blockHeader + 6 * static_cast<std::size_t>(c[6]))
        {
            fail("part " + std::to_string(p) + ": inconsistent slot count");
        }
        const IndexBox b = boxAt(c, windowStateHeaderSize);
        if (b.empty() || b.intersected(block) != b)
        {
            fail("part " + std::to_string(p) + "'s block " + boxText(b) + " outside " + boxText(block));
        }
        for (std::size_t q = 0; q < p; ++q)
        {
            if (!b.intersected(boxAt(parts[q].counters, windowStateHeaderSize)).empty())
            {
                fail("parts " + std::to_string(q) + " and " + std::to_string(p) + " overlap");
            }
        }
        nodes += b.nodeCount();
        std::size_t values = 0;
        for (std::size_t slot = 0; slot < static_cast<std::size_t>(c[6]); ++slot)
        {
            const IndexBox s = boxAt(c, blockHeader + 6 * slot);
            if (!s.empty() && s.intersected(b) != s)
            {
                fail("part " + std::to_string(p) + "'s slot box " + boxText(s) + " outside its block");
            }
            values += s.nodeCount() * static_cast<std::size_t>(c[4]);
        }
        if (values != parts[p].values.size())
        {
            fail("part " + std::to_string(p) + " holds " + std::to_string(parts[p].values.size())
                 + " values, its slot boxes " + std::to_string(values));
        }
    }
    if (nodes != block.nodeCount())
    {
        fail("the parts hold " + std::to_string(nodes) + " of the block's "
             + std::to_string(block.nodeCount()) + " nodes");
    }
}

IndexBox windowPartBlock(const WindowState& part)
{
    return boxAt(part.counters, windowStateHeaderSize);
}

IndexBox windowPartSlotBox(const WindowState& part, std::size_t slot)
{
    return boxAt(part.counters, blockHeader + 6 * slot);
}

namespace
{

// Part values of slot box `from` into the joined slot's values over `to`.
void copyInto(const double* from, const IndexBox& fromBox, const IndexBox& toBox, std::size_t q,
              std::vector<double>& to, std::size_t toOffset)
{
    forEachRowIn(fromBox, toBox,
                 [&](const IndexRow& row)
                 {
                     std::copy(from + row.offsetInBox * q, from + (row.offsetInBox + row.length) * q,
                               to.begin() + static_cast<std::ptrdiff_t>(toOffset + row.first * q));
                 });
}

} // namespace

WindowState joinedWindowState(const std::vector<WindowState>& parts, const IndexBox& block)
{
    checkWindowParts(parts, block);
    const std::vector<std::int64_t>& first = parts.front().counters;
    const std::size_t q = static_cast<std::size_t>(first[4]);
    const std::size_t filled = static_cast<std::size_t>(first[6]);
    WindowState joined;
    joined.counters.assign(first.begin(), first.begin() + windowStateHeaderSize);
    appendBox(joined.counters, block);
    std::vector<std::size_t> position(parts.size(), 0);
    for (std::size_t s = 0; s < filled; ++s)
    {
        IndexBox slot;
        for (const WindowState& part : parts)
        {
            slot = slot.united(boxAt(part.counters, blockHeader + 6 * s));
        }
        appendBox(joined.counters, slot);
        const std::size_t offset = joined.values.size();
        joined.values.resize(offset + slot.nodeCount() * q, 0.0);
        for (std::size_t p = 0; p < parts.size(); ++p)
        {
            const IndexBox from = boxAt(parts[p].counters, blockHeader + 6 * s);
            if (position[p] + from.nodeCount() * q > parts[p].values.size())
            {
                fail("part " + std::to_string(p) + " holds fewer values than its slot boxes");
            }
            copyInto(parts[p].values.data() + position[p], from, slot, q, joined.values, offset);
            position[p] += from.nodeCount() * q;
        }
    }
    for (std::size_t p = 0; p < parts.size(); ++p)
    {
        if (position[p] != parts[p].values.size())
        {
            fail("part " + std::to_string(p) + " holds more values than its slot boxes");
        }
    }
    return joined;
}

} // namespace dropletFiber
