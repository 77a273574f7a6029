// LiveBox: the part of a block's owned box that its arrays cover (the step values, the
// averaging window's slots, total and stamps): the nodes its steps have touched, grown
// ahead of a spray that spreads (docs/scaleOut.md, memory per processor).
//
// Growth rule (grownLiveBox): where a box reaches nodes of the block outside the live
// box, each side that must move goes past the union of the two by a margin of half the
// union's extent in that direction (at least liveBoxMinimumMargin nodes), clipped to the
// block; the sides that need not move stay. Why half: a regrowth re-allocates and copies
// the W + 2 arrays of the whole live box (W + 1 times 56 bytes per node, the cost of a
// window's fill), so the regrowths of a spray that spreads must grow the box
// geometrically: each at least 1.5 times in the direction pushed, and all of them
// together cost at most about 3 fills of the final live box (a quarter, 1.25 times per
// regrowth, measured 5 fills: bench/scaleOut.sh -localised, 12 regrowths in 60 steps);
// the box stays within 1.5 times the touched nodes' extent plus the margin per direction
// pushed. A spray that stays put costs nothing after its first step.
#pragma once

#include "grid/GridSpec.hpp"

#include <algorithm>
#include <cstddef>

namespace dropletFiber
{

// Nodes added beyond a regrown side at least (small sprays regrow less often).
constexpr int liveBoxMinimumMargin = 2;

// The live box after `touched` (grid indices) is written: `live` itself when the part of
// touched inside `block` lies in it, else the rule above (a box inside block).
IndexBox grownLiveBox(const IndexBox& live, const IndexBox& touched, const IndexBox& block);

// Copies the values of the nodes of `box` (inside both layouts; q values per node) from
// an array laid out over fromLayout to one laid out over toLayout (flatIndexInBox).
template <class T>
void copyBoxValues(const T* from, const IndexBox& fromLayout, T* to, const IndexBox& toLayout,
                   const IndexBox& box, std::size_t q)
{
    forEachRowIn(box, fromLayout,
                 [&](const IndexRow& row)
                 {
                     const std::size_t target = flatIndexInBox(toLayout, box.lo[0], row.j + fromLayout.lo[1],
                                                               row.k + fromLayout.lo[2]);
                     std::copy(from + row.first * q, from + (row.first + row.length) * q, to + target * q);
                 });
}

} // namespace dropletFiber
