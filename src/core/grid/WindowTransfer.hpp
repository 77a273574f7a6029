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

} // namespace dropletFiber
