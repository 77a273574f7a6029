#include "grid/MultilinearWeights.hpp"

#include <algorithm>
#include <cmath>

namespace dropletFiber
{

CornerWeights multilinearWeights(const GridSpec& spec, const Eigen::Vector3d& point)
{
    // Per direction: lower corner index and the fraction towards the next node.
    std::array<int, 3> base{};
    std::array<double, 3> fraction{};
    std::array<int, 3> extent{};
    for (int d = 0; d < 3; ++d)
    {
        if (spec.flat(d))
        {
            base[d] = 0;
            fraction[d] = 0.0;
            extent[d] = 1;
            continue;
        }
        const AxisCell position = axisCell(point[d], spec.lower[d], spec.spacing(d), spec.nodes[d]);
        base[d] = position.cell;
        fraction[d] = position.fraction;
        extent[d] = 2;
    }
    CornerWeights result;
    result.lowerCorner = base;
    for (int c = 0; c < extent[2]; ++c)
    {
        const double wz = extent[2] == 1 ? 1.0 : (c == 0 ? 1.0 - fraction[2] : fraction[2]);
        for (int b = 0; b < extent[1]; ++b)
        {
            const double wy = extent[1] == 1 ? 1.0 : (b == 0 ? 1.0 - fraction[1] : fraction[1]);
            for (int a = 0; a < extent[0]; ++a)
            {
                const double wx = extent[0] == 1 ? 1.0 : (a == 0 ? 1.0 - fraction[0] : fraction[0]);
                result.node[result.count] = spec.flatIndex(base[0] + a, base[1] + b, base[2] + c);
                result.weight[result.count] = wx * wy * wz;
                ++result.count;
            }
        }
    }
    return result;
}

bool insideActiveBox(const GridSpec& spec, const Eigen::Vector3d& point, double relativeTolerance)
{
    for (int d = 0; d < 3; ++d)
    {
        if (spec.flat(d))
        {
            continue;
        }
        const double tolerance = relativeTolerance * (spec.upper[d] - spec.lower[d]);
        if (!(point[d] >= spec.lower[d] - tolerance && point[d] <= spec.upper[d] + tolerance))
        {
            return false;
        }
    }
    return true;
}

} // namespace dropletFiber
