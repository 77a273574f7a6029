// LayingZone: where along the belt's motion fibers are laid, and which rows of the mat
// are complete (docs/model.md sec. 11, P48). In the fixed frame a fiber's foot lies at
// f = V t - along; the zone is [footMin, footMax] of the feet seen, widened by the
// furthest a footprint reached along beyond its fiber's centre (P58, P59). The mat's row
// at `along` a passes footMin at (a + footMin) / V and leaves footMax at (a + footMax) / V:
// it is complete once it has left the zone, having entered it after the laying began (the
// first fiber, or a later time given as steady), so that it holds a whole crossing of the
// steady laying and no fiber will be added to it.
#pragma once

#include "laydown/Belt.hpp"

#include <utility>

namespace dropletFiber
{

struct LayingZone
{
    double firstTime = -1.0; // the first fiber's time (-1: none laid)
    double footMin = 1e300, footMax = -1e300;
    double reach = 0.0; // m, along beyond a centre

    // Widens the zone by a fiber laid on a belt moving at `speed`.
    void add(const LaidFiber& fiber, double speed);

    // The complete rows [first, last] of cells `cell` at `time` (first > last: none) on a
    // moving belt (speed > 0), of the rows that entered the zone after max(first fiber's
    // time, steadyFrom).
    std::pair<long, long> completeRows(double speed, double cell, double steadyFrom, double time) const;
};

} // namespace dropletFiber
