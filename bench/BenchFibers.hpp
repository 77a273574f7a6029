// BenchFibers: the fibers of fiberStepBench and fiberScalingBench (flexible glass
// fibers, r = 5 um, 1 cm, gently bent, every third pinned at its start), one
// definition so that both programs time the same fibers.
#pragma once

#include "fiber/FiberSolver.hpp"

#include <cmath>
#include <vector>

namespace bench
{

inline std::vector<dropletFiber::Fiber> makeFibers(int fiberCount, int pointCount)
{
    using namespace dropletFiber;
    std::vector<Fiber> fibers;
    fibers.reserve(static_cast<std::size_t>(fiberCount));
    const FiberMaterial glass{5e-6, 2500.0, 7e10};
    for (int f = 0; f < fiberCount; ++f)
    {
        // Deterministic spread of positions and orientations.
        const double a = 0.7 * f, b = 0.3 * f;
        const Eigen::Vector3d start(0.02 * std::cos(a), 0.02 * std::sin(a), 0.001 * f);
        const Eigen::Vector3d direction(std::cos(b), std::sin(b), 0.3 * std::sin(a));
        Eigen::Matrix3Xd points(3, pointCount);
        const int segments = pointCount - 1;
        for (int i = 0; i < pointCount; ++i)
        {
            // a gentle bend so bending is active from the start
            const double s = static_cast<double>(i) / segments;
            points.col(i) = start + 0.01 * s * direction.normalized()
                + Eigen::Vector3d(0.0, 0.0, 5e-4 * std::sin(M_PI * s));
        }
        const EndCondition startEnd = f % 3 == 0 ? EndCondition::pinnedEnd() : EndCondition::freeEnd();
        fibers.emplace_back(points, glass, startEnd, EndCondition::freeEnd());
    }
    return fibers;
}

} // namespace bench
