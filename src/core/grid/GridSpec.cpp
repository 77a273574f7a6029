#include "grid/GridSpec.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dropletFiber
{

std::string boxText(const IndexBox& box)
{
    return "(" + std::to_string(box.lo[0]) + " " + std::to_string(box.lo[1]) + " " + std::to_string(box.lo[2])
        + ") to (" + std::to_string(box.hi[0]) + " " + std::to_string(box.hi[1]) + " "
        + std::to_string(box.hi[2]) + ")";
}

std::size_t IndexBox::nodeCount() const
{
    if (empty())
    {
        return 0;
    }
    std::size_t n = 1;
    for (int d = 0; d < 3; ++d)
    {
        n *= static_cast<std::size_t>(hi[d] - lo[d] + 1);
    }
    return n;
}

IndexBox IndexBox::united(const IndexBox& other) const
{
    if (empty())
    {
        return other;
    }
    if (other.empty())
    {
        return *this;
    }
    IndexBox box;
    for (int d = 0; d < 3; ++d)
    {
        box.lo[d] = std::min(lo[d], other.lo[d]);
        box.hi[d] = std::max(hi[d], other.hi[d]);
    }
    return box;
}

IndexBox IndexBox::intersected(const IndexBox& other) const
{
    IndexBox box;
    for (int d = 0; d < 3; ++d)
    {
        box.lo[d] = std::max(lo[d], other.lo[d]);
        box.hi[d] = std::min(hi[d], other.hi[d]);
    }
    return box.empty() ? IndexBox{} : box;
}

std::array<int, 3> IndexBox::extents() const
{
    if (empty())
    {
        return {{0, 0, 0}};
    }
    return {{hi[0] - lo[0] + 1, hi[1] - lo[1] + 1, hi[2] - lo[2] + 1}};
}

void GridSpec::validate() const
{
    static const char* axis[3] = {"x", "y", "z"};
    for (int d = 0; d < 3; ++d)
    {
        if (nodes[d] < 1)
        {
            throw std::invalid_argument(std::string("grid: nodes in ") + axis[d] + " must be at least 1, got "
                                        + std::to_string(nodes[d]));
        }
        if (!std::isfinite(lower[d]) || !std::isfinite(upper[d]))
        {
            throw std::invalid_argument(std::string("grid: bounds in ") + axis[d] + " are not finite");
        }
        if (!(upper[d] > lower[d]))
        {
            throw std::invalid_argument(
                std::string("grid: upper bound must exceed lower bound in ") + axis[d]
                + (flat(d) ? " (a single-node direction needs its thickness as upper - lower)" : ""));
        }
    }
    if (activeDimensions() == 0)
    {
        throw std::invalid_argument("grid: at least one direction needs 2 or more nodes");
    }
    const double total = static_cast<double>(nodes[0]) * nodes[1] * nodes[2];
    if (total > maxNodes)
    {
        throw std::invalid_argument("grid: more than 1e10 nodes");
    }
}

int GridSpec::activeDimensions() const
{
    int n = 0;
    for (int d = 0; d < 3; ++d)
    {
        n += flat(d) ? 0 : 1;
    }
    return n;
}

double GridSpec::spacing(int d) const
{
    return flat(d) ? upper[d] - lower[d] : (upper[d] - lower[d]) / (nodes[d] - 1);
}

double GridSpec::nodeVolume() const
{
    return spacing(0) * spacing(1) * spacing(2);
}

int GridSpec::boundaryDirections(int i, int j, int k) const
{
    const std::array<int, 3> index{{i, j, k}};
    int count = 0;
    for (int d = 0; d < 3; ++d)
    {
        const bool onFace
            = index[static_cast<std::size_t>(d)] == 0 || index[static_cast<std::size_t>(d)] == nodes[d] - 1;
        count += !flat(d) && onFace ? 1 : 0;
    }
    return count;
}

double GridSpec::dualVolume(int i, int j, int k) const
{
    return std::ldexp(nodeVolume(), -boundaryDirections(i, j, k));
}

std::size_t GridSpec::nodeCount() const
{
    return static_cast<std::size_t>(nodes[0]) * static_cast<std::size_t>(nodes[1])
        * static_cast<std::size_t>(nodes[2]);
}

IndexBox GridSpec::fullBox() const
{
    IndexBox box;
    box.lo = {{0, 0, 0}};
    box.hi = {{nodes[0] - 1, nodes[1] - 1, nodes[2] - 1}};
    return box;
}

double GridSpec::nodeCoordinate(int d, int index) const
{
    if (flat(d))
    {
        return 0.5 * (lower[d] + upper[d]);
    }
    // The last node is placed exactly on the upper bound (no accumulated round-off).
    if (index == nodes[d] - 1)
    {
        return upper[d];
    }
    return lower[d] + index * spacing(d);
}

Eigen::Vector3d GridSpec::nodePosition(int i, int j, int k) const
{
    return Eigen::Vector3d(nodeCoordinate(0, i), nodeCoordinate(1, j), nodeCoordinate(2, k));
}

bool GridSpec::contains(const Eigen::Vector3d& point) const
{
    for (int d = 0; d < 3; ++d)
    {
        if (!(point[d] >= lower[d] && point[d] <= upper[d]))
        {
            return false;
        }
    }
    return true;
}

bool sameLattice(const GridSpec& a, const GridSpec& b)
{
    return a.lower == b.lower && a.upper == b.upper && a.nodes == b.nodes;
}

} // namespace dropletFiber
