#include "grid/CloudInCellWeights.hpp"

#include "grid/MultilinearWeights.hpp"

#include <algorithm>
#include <cmath>

namespace dropletFiber
{

namespace
{

// Points at most half the smallest node spacing apart along the path (at least one, at
// most 4096), at the middles of equal parts; each carries `share` of the parcel.
struct PathPoints
{
    PathPoints(const Eigen::Vector3d& pathStart, const Eigen::Vector3d& pathDisplacement,
               double smallestSpacing)
        : start(pathStart), displacement(pathDisplacement),
          count(static_cast<int>(
              std::min(4096.0, std::max(1.0, std::ceil(2.0 * pathDisplacement.norm() / smallestSpacing))))),
          share(1.0 / count)
    {
    }

    Eigen::Vector3d at(int p) const { return start + ((p + 0.5) * share) * displacement; }

    Eigen::Vector3d start;
    Eigen::Vector3d displacement;
    int count;
    double share;
};

// The box of the cells' corners of all points of a path, with its strides (i fastest).
struct PathCells
{
    IndexBox box;
    std::array<std::size_t, 3> stride{};
    std::size_t nodeCount = 1;
};

// The corners of all points lie in the box spanned by the cells of the first and the last
// point: along a straight path the cell is non-decreasing or non-increasing per direction
// (axisCell). Summing the points' weights per node of that box first, and adding the
// parcel's seven quantities once per node that got weight, makes a path of 10 points touch
// ~12 distinct nodes of a 2D grid instead of 40 corner updates.
PathCells pathCells(const GridSpec& spec, const std::array<double, 3>& spacing, const PathPoints& points)
{
    const Eigen::Vector3d firstPoint = points.at(0);
    const Eigen::Vector3d lastPoint = points.at(points.count - 1);
    PathCells cells;
    for (int d = 0; d < 3; ++d)
    {
        const auto u = static_cast<std::size_t>(d);
        if (spec.flat(d))
        {
            cells.box.lo[u] = cells.box.hi[u] = 0;
        }
        else
        {
            const AxisCell first = axisCell(firstPoint[d], spec.lower[d], spacing[u], spec.nodes[d]);
            const AxisCell last = axisCell(lastPoint[d], spec.lower[d], spacing[u], spec.nodes[d]);
            cells.box.lo[u] = std::min(first.cell, last.cell);
            cells.box.hi[u] = std::max(first.cell, last.cell) + 1;
        }
        cells.stride[u] = cells.nodeCount;
        cells.nodeCount *= static_cast<std::size_t>(cells.box.hi[u] - cells.box.lo[u] + 1);
    }
    return cells;
}

// Adds share times the multilinear weights of the point's cell corners to weights (one
// value per node of cells.box): the same products, in the same order, as multilinearWeights.
void addCornerWeights(const GridSpec& spec, const std::array<double, 3>& spacing, const PathCells& cells,
                      const Eigen::Vector3d& point, double share, double* weights)
{
    // Per direction: the weights of the lower and upper corner and the offset of the lower
    // corner in the box (flat directions: one corner of weight 1)
    std::array<double, 3> lowerWeight{{1.0, 1.0, 1.0}}, upperWeight{{0.0, 0.0, 0.0}};
    std::size_t offset = 0;
    for (int d = 0; d < 3; ++d)
    {
        const auto u = static_cast<std::size_t>(d);
        if (spec.flat(d))
        {
            continue;
        }
        const AxisCell position = axisCell(point[d], spec.lower[d], spacing[u], spec.nodes[d]);
        lowerWeight[u] = 1.0 - position.fraction;
        upperWeight[u] = position.fraction;
        offset += cells.stride[u] * static_cast<std::size_t>(position.cell - cells.box.lo[u]);
    }
    const int extentZ = spec.flat(2) ? 1 : 2;
    const int extentY = spec.flat(1) ? 1 : 2;
    const int extentX = spec.flat(0) ? 1 : 2;
    for (int c = 0; c < extentZ; ++c)
    {
        const double wz = c == 0 ? lowerWeight[2] : upperWeight[2];
        for (int b = 0; b < extentY; ++b)
        {
            const double wy = b == 0 ? lowerWeight[1] : upperWeight[1];
            double* row = weights + offset + cells.stride[2] * static_cast<std::size_t>(c)
                + cells.stride[1] * static_cast<std::size_t>(b);
            row[0] += share * (lowerWeight[0] * wy * wz);
            if (extentX == 2)
            {
                row[1] += share * (upperWeight[0] * wy * wz);
            }
        }
    }
}

// One point's share on the corners of its cell (paths across many cells).
void sendCorners(const GridSpec& spec, const Eigen::Vector3d& point, double share, WeightSink& sink)
{
    const CornerWeights cornerWeights = multilinearWeights(spec, point);
    for (int c = 0; c < cornerWeights.count; ++c)
    {
        const auto u = static_cast<std::size_t>(c);
        sink.add(cornerWeights.node[u], share * cornerWeights.weight[u]);
    }
}

// The path's weights summed per node of its cell box into the sink.
void sendPathWeights(const std::array<int, 3>& nodes, const std::vector<double>& weights, const IndexBox& box,
                     WeightSink& sink)
{
    std::int64_t weighted = 0;
    forEachRow(box, nodes,
               [&](const IndexRow& row)
               {
                   for (std::size_t i = 0; i < row.length; ++i)
                   {
                       const double weight = weights[row.offsetInBox + i];
                       if (weight > 0.0)
                       {
                           sink.add(row.first + i, weight);
                           ++weighted;
                       }
                   }
               });
    sink.statistics().nodesWeighted += weighted;
}

} // namespace

IndexBox CloudInCellWeights::box(const NodeLattice& lattice, const Eigen::Vector3d& start,
                                 const Eigen::Vector3d& displacement) const
{
    // The box of the half-spacing points holds that of the finer points near a face (both
    // span the cells of the path's first and last point).
    const PathPoints points(start, displacement, lattice.smallestSpacing());
    const PathCells coarse = pathCells(lattice.spec(), lattice.spacings(), points);
    if (displacement.squaredNorm() > 0.0 && lattice.touchesFace(coarse.box))
    {
        return pathCells(lattice.spec(), lattice.spacings(),
                         PathPoints(start, displacement, lattice.smallestSpacing() / faceRefinement))
            .box;
    }
    return coarse.box;
}

void CloudInCellWeights::weigh(const NodeLattice& lattice, const Eigen::Vector3d& start,
                               const Eigen::Vector3d& displacement, WeightSink& sink)
{
    const GridSpec& spec = lattice.spec();
    PathPoints points(start, displacement, lattice.smallestSpacing());
    PathCells cells = pathCells(spec, lattice.spacings(), points);
    if (displacement.squaredNorm() > 0.0 && lattice.touchesFace(cells.box))
    {
        // Near a face: finer points (faceRefinement; a stationary parcel is one point).
        points = PathPoints(start, displacement, lattice.smallestSpacing() / faceRefinement);
        cells = pathCells(spec, lattice.spacings(), points);
    }
    if (!sink.wants(cells.box))
    {
        return;
    }
    sink.beginCells(cells.box);
    const int corners = (spec.flat(0) ? 1 : 2) * (spec.flat(1) ? 1 : 2) * (spec.flat(2) ? 1 : 2);
    sink.statistics().nodesVisited += static_cast<std::int64_t>(points.count) * corners;

    if (cells.nodeCount > maximumPathBoxNodes)
    {
        // A path across many cells (rare: parcels move a few cells per step at most): each
        // point's corners straight into the sink.
        for (int p = 0; p < points.count; ++p)
        {
            sendCorners(spec, points.at(p), points.share, sink);
        }
        sink.statistics().nodesWeighted += static_cast<std::int64_t>(points.count) * corners;
        return;
    }
    pathWeights_.assign(cells.nodeCount, 0.0);
    for (int p = 0; p < points.count; ++p)
    {
        addCornerWeights(spec, lattice.spacings(), cells, points.at(p), points.share, pathWeights_.data());
    }
    sendPathWeights(spec.nodes, pathWeights_, cells.box, sink);
}

} // namespace dropletFiber
