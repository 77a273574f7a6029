#include "grid/NodeLattice.hpp"

#include <algorithm>
#include <cmath>

namespace dropletFiber
{

namespace
{

// True when [lo, hi] holds an index congruent to offset modulo period (> 0).
bool holdsMultiple(int lo, int hi, int period, int offset)
{
    const int ahead = ((offset - lo) % period + period) % period; // from lo to the next one
    return lo + ahead <= hi;
}

} // namespace

NodeLattice::NodeLattice(const GridSpec& spec) : spec_(spec)
{
    for (int d = 0; d < 3; ++d)
    {
        // The lattice lower + i h, from one grid length before the box to one after it
        // (ghost nodes of the folded kernels); the nodes keep GridSpec's coordinates.
        const int nodes = spec.nodes[d];
        ghostLayers_[d] = spec.flat(d) ? 0 : nodes - 1;
        coordinates_[d].resize(static_cast<std::size_t>(nodes + 2 * ghostLayers_[d]));
        for (int i = -ghostLayers_[d]; i < nodes + ghostLayers_[d]; ++i)
        {
            const bool node = i >= 0 && i < nodes;
            coordinates_[d][static_cast<std::size_t>(i + ghostLayers_[d])]
                = node ? spec.nodeCoordinate(d, i) : spec.lower[d] + i * spec.spacing(d);
        }
        inverseSpacing_[d] = spec.flat(d) ? 0.0 : 1.0 / spec.spacing(d);
        spacing_[d] = spec.flat(d) ? 0.0 : spec.spacing(d);
        largestSpacing_ = spec.flat(d) ? largestSpacing_ : std::max(largestSpacing_, spec.spacing(d));
        if (!spec.flat(d))
        {
            smallestSpacing_
                = smallestSpacing_ > 0.0 ? std::min(smallestSpacing_, spec.spacing(d)) : spec.spacing(d);
        }
        halfCellDiagonal_ += spec.flat(d) ? 0.0 : 0.25 * spec.spacing(d) * spec.spacing(d);
    }
    halfCellDiagonal_ = std::sqrt(halfCellDiagonal_);
}

IndexBox NodeLattice::nodeBox(const ClippedPath& path, double reach) const
{
    IndexBox box;
    for (int d = 0; d < 3; ++d)
    {
        if (spec_.flat(d))
        {
            box.lo[d] = box.hi[d] = 0;
            continue;
        }
        // Lattice indices, ghost nodes included (at most ghostLayers_ beyond each face).
        const double a = std::min(path.start[d], path.start[d] + path.displacement[d]) - reach;
        const double b = std::max(path.start[d], path.start[d] + path.displacement[d]) + reach;
        const double lowest = -ghostLayers_[d];
        const double highest = spec_.nodes[d] - 1 + ghostLayers_[d];
        const double first = std::ceil((a - spec_.lower[d]) * inverseSpacing_[d]);
        const double lastReached = std::floor((b - spec_.lower[d]) * inverseSpacing_[d]);
        box.lo[d] = static_cast<int>(std::min(std::max(first, lowest), highest));
        box.hi[d] = static_cast<int>(std::min(std::max(lastReached, lowest - 1.0), highest));
    }
    return box;
}

bool NodeLattice::touchesFace(const IndexBox& box) const
{
    for (int d = 0; d < 3; ++d)
    {
        if (!spec_.flat(d) && (box.lo[d] == 0 || box.hi[d] == spec_.nodes[d] - 1))
        {
            return true;
        }
    }
    return false;
}

bool NodeLattice::withinGrid(const IndexBox& box) const
{
    for (int d = 0; d < 3; ++d)
    {
        if (box.lo[d] < 0 || box.hi[d] > spec_.nodes[d] - 1)
        {
            return false;
        }
    }
    return true;
}

IndexBox NodeLattice::foldedBox(const IndexBox& box) const
{
    // The mirror image is a tent of period 2 last: rising from 0 at the even multiples of
    // last to last at the odd ones. Over [lo, hi] its least value is 0 where the range holds
    // an even multiple, else at an end; its largest is last where it holds an odd one.
    IndexBox folded;
    for (int d = 0; d < 3; ++d)
    {
        if (box.lo[d] > box.hi[d])
        {
            folded.lo[d] = spec_.nodes[d];
            folded.hi[d] = -1;
            continue;
        }
        const int a = spec_.mirrorIndex(d, box.lo[d]);
        const int b = spec_.mirrorIndex(d, box.hi[d]);
        const int last = spec_.nodes[d] - 1;
        const bool holdsEven = last > 0 && holdsMultiple(box.lo[d], box.hi[d], 2 * last, 0);
        const bool holdsOdd = last > 0 && holdsMultiple(box.lo[d], box.hi[d], 2 * last, last);
        folded.lo[d] = holdsEven ? 0 : std::min(a, b);
        folded.hi[d] = holdsOdd ? last : std::max(a, b);
    }
    return folded;
}

IndexBox NodeLattice::mirror(const IndexBox& box, MirrorImages& images) const
{
    IndexBox folded;
    for (int d = 0; d < 3; ++d)
    {
        std::vector<int>& image = images[static_cast<std::size_t>(d)];
        image.clear();
        folded.lo[d] = spec_.nodes[d];
        folded.hi[d] = -1;
        for (int i = box.lo[d]; i <= box.hi[d]; ++i)
        {
            image.push_back(spec_.mirrorIndex(d, i));
            folded.lo[d] = std::min(folded.lo[d], image.back());
            folded.hi[d] = std::max(folded.hi[d], image.back());
        }
    }
    return folded;
}

} // namespace dropletFiber
