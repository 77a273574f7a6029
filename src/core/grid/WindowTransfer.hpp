// WindowTransfer: an averaging window moved to a new block of the grid when the grid
// blocks are re-partitioned (docs/scaleOut.md, balanced blocks). Each old block saves
// the part of its window the new block holds (AveragingWindow::savePart, node values);
// the new block joins the parts into one state of its own box, which
// AveragingWindow::restore reads. Every slot keeps its node values, so the new window's
// slots and total are those of the old windows, bit for bit: a re-partition changes no
// field.
#pragma once

#include "grid/AveragingWindow.hpp"

#include <vector>

namespace dropletFiber
{

// The format-2 state of `block` from parts (format 2, from savePart) whose blocks are
// disjoint and together hold every node of `block`: per slot, the smallest box holding
// the parts' slot boxes, zero between them. The parts must share the grid, quantities,
// window length, filled and committed steps (windows stepped together). Throws
// std::invalid_argument naming what does not fit.
WindowState joinedWindowState(const std::vector<WindowState>& parts, const IndexBox& block);

// Throws std::invalid_argument (as joinedWindowState) unless the parts can be joined over
// `block`: the same grid and window, blocks disjoint and holding all of `block`, each
// part's values those of its slot boxes, each slot box inside its part's block.
void checkWindowParts(const std::vector<WindowState>& parts, const IndexBox& block);
// A part's block and its slot boxes (grid indices; empty where the slot is zero).
IndexBox windowPartBlock(const WindowState& part);
IndexBox windowPartSlotBox(const WindowState& part, std::size_t slot);

} // namespace dropletFiber
