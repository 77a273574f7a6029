// FormingLine: the mat of a line of k identical hoods along one belt, built from one
// hood's mat (docs/model.md sec. 11, P62). A plant lays several spinners' veils onto one
// belt; in a steady laying each hood adds to a row what one hood adds in a whole crossing.
// Approximation: the k hoods' crossings are k of the one hood's complete rows, `shift`
// rows apart (periodically within the complete rows [rowFrom, rowTo]): each row of the
// line is the sum of k rows laid at different times by different computed fibers, which
// are independent draws when their rows lie further apart than a footprint reaches and
// than the laying's correlation in time. The error sums add as the variances of
// independent draws do. The hoods stand at the same place across (no offset).
#pragma once

#include "laydown/MatMap.hpp"

namespace dropletFiber
{

// The line's map over the rows [rowFrom, rowTo] (its other rows empty). Throws
// std::invalid_argument unless hoods >= 1, shift >= 1 and (hoods - 1) shift < the rows.
MatMap formingLine(const MatMap& hood, long rowFrom, long rowTo, int hoods, long shift);

// The shift that spreads k hoods evenly over n complete rows: n / k (at least 1).
long evenShift(long rows, int hoods);

} // namespace dropletFiber
