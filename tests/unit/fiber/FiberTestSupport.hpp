// Shared set-up for the fiber unit tests: straight and shaped fibers, a stepping loop
// that checks inextensibility after every step, and period measurement.
#pragma once

#include "fiber/FiberSolver.hpp"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

namespace dropletFiber::test
{

// Glass fiber (r = 5 um).
inline FiberMaterial glassFiber()
{
    return FiberMaterial{5e-6, 2500.0, 7e10};
}

// segments+1 points from start along direction (normalised), total length.
inline Eigen::Matrix3Xd straightPoints(int segments, const Eigen::Vector3d& start,
                                       const Eigen::Vector3d& direction, double length)
{
    Eigen::Matrix3Xd points(3, segments + 1);
    const Eigen::Vector3d step = direction.normalized() * (length / segments);
    for (int i = 0; i <= segments; ++i)
        points.col(i) = start + i * step;
    return points;
}

// Points with segment length exactly length/segments, following a lateral offset
// w(s) (in direction lateral) from a base line along axis: the axial advance of each
// segment is sqrt(l^2 - dw^2), so the strip is exactly inextensible at t = 0.
inline Eigen::Matrix3Xd offsetPoints(int segments, const Eigen::Vector3d& start, const Eigen::Vector3d& axis,
                                     const Eigen::Vector3d& lateral, double length,
                                     const std::function<double(double)>& offset)
{
    Eigen::Matrix3Xd points(3, segments + 1);
    const double l = length / segments;
    double axial = 0.0;
    double previous = offset(0.0);
    points.col(0) = start + previous * lateral;
    for (int i = 1; i <= segments; ++i)
    {
        const double w = offset(i * l);
        axial += std::sqrt(l * l - (w - previous) * (w - previous));
        points.col(i) = start + axial * axis + w * lateral;
        previous = w;
    }
    return points;
}

// Steps fibers `steps` times; checks segment lengths after every step and returns
// the worst relative segment-length error seen.
struct RunSummary
{
    double worstSegmentError = 0.0;
    int subSteps = 0;
    int newtonIterations = 0;
    int maxSubStepsOfAFiber = 0;
};

// The air as a function of position: sampled at airSamplePoints(fibers) before every
// step, as the OpenFOAM layer samples its fields.
using AirField = std::function<AirSample(const Eigen::Matrix3Xd& points)>;

inline RunSummary run(FiberSolver& solver, std::vector<Fiber>& fibers, double dt, int steps,
                      const AirField& air, const std::function<void(int, const StepReport&)>& observe = {})
{
    RunSummary summary;
    for (int k = 0; k < steps; ++k)
    {
        const StepReport report = solver.step(fibers, dt, air(airSamplePoints(fibers)));
        summary.worstSegmentError = std::max(summary.worstSegmentError, report.maxSegmentLengthError);
        summary.subSteps += report.subSteps;
        summary.newtonIterations += report.newtonIterations;
        summary.maxSubStepsOfAFiber = std::max(summary.maxSubStepsOfAFiber, report.maxSubStepsOfAFiber);
        if (observe)
            observe(k, report);
    }
    return summary;
}

// The same with one sample for every step (no air, or air that does not depend on
// position such as uniformAir(fibers, ...)).
inline RunSummary run(FiberSolver& solver, std::vector<Fiber>& fibers, double dt, int steps,
                      const AirSample& air = AirSample(),
                      const std::function<void(int, const StepReport&)>& observe = {})
{
    return run(
        solver, fibers, dt, steps, [&air](const Eigen::Matrix3Xd&) { return air; }, observe);
}

// Mean period from the upward zero crossings of a sampled signal (linear interpolation).
inline double meanPeriod(const std::vector<double>& times, const std::vector<double>& signal)
{
    std::vector<double> crossings;
    for (std::size_t k = 1; k < signal.size(); ++k)
    {
        if (signal[k - 1] < 0.0 && signal[k] >= 0.0)
        {
            const double f = signal[k - 1] / (signal[k - 1] - signal[k]);
            crossings.push_back(times[k - 1] + f * (times[k] - times[k - 1]));
        }
    }
    if (crossings.size() < 2)
        return std::nan("");
    return (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

} // namespace dropletFiber::test
