#include "grid/LiveBox.hpp"

#include <algorithm>

namespace dropletFiber
{

IndexBox grownLiveBox(const IndexBox& live, const IndexBox& touched, const IndexBox& block)
{
    const IndexBox reached = touched.intersected(block);
    if (reached.empty() || reached.intersected(live) == reached)
    {
        return live;
    }
    const IndexBox joined = live.united(reached);
    IndexBox grown = joined;
    for (int d = 0; d < 3; ++d)
    {
        const int margin = std::max(liveBoxMinimumMargin, (joined.hi[d] - joined.lo[d] + 1) / 2);
        // Only the sides the touched box pushed out move (an empty live box: all of them)
        if (live.empty() || reached.lo[d] < live.lo[d])
        {
            grown.lo[d] = std::max(block.lo[d], joined.lo[d] - margin);
        }
        if (live.empty() || reached.hi[d] > live.hi[d])
        {
            grown.hi[d] = std::min(block.hi[d], joined.hi[d] + margin);
        }
    }
    return grown;
}

} // namespace dropletFiber
