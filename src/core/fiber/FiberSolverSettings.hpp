// FiberSolverSettings: everything the fiber solver is configured with. Defaults are
// the ones the tests and the OpenFOAM layer use unless a case says otherwise.
#pragma once

#include "fiber/DragModel.hpp"

#include <Eigen/Core>

namespace dropletFiber
{

struct FiberSolverSettings
{
    Eigen::Vector3d gravity = Eigen::Vector3d(0.0, 0.0, -9.81); // [m/s^2]
    DragSettings drag;

    // Time scheme: theta = 1/2 is the implicit midpoint rule (second order, no
    // numerical damping, conserves energy exactly with these quadratic constraints
    // and bending energy); theta = 1 is backward Euler (first order, damps, and with a
    // very large step solves the static equilibrium). Values in [1/2, 1].
    double theta = 0.5;

    // Newton convergence: relative segment-length error, residual relative to the
    // size of its terms, and Newton update relative to the shortest segment.
    double constraintTolerance = 1e-13;
    double residualTolerance = 1e-12;
    double updateTolerance = 1e-12;
    int maxNewtonIterations = 20;
    // A sub-step whose Newton stalls at round-off is still accepted when its
    // constraints hold to this (and counted in StepReport::looseConvergences).
    double acceptableConstraintError = 1e-10;

    // Sub-stepping, per fiber, only where accuracy needs it: a sub-step is halved
    // when Newton fails or when some segment turns by more than maxSegmentRotation
    // [rad]; the step is also split up front so that it is at most
    // maxDragStepRatio drag relaxation times sigma / c_n (the midpoint rule turns a
    // relaxation much faster than the step into a sign-flipping ring). The stiff
    // bending modes never force sub-steps: the scheme is unconditionally stable.
    int maxSubSteps = 256;
    double maxSegmentRotation = 0.2;
    double maxDragStepRatio = 2.0;

    // Also project velocities onto the inextensible motions after every sub-step
    // (mass-weighted, see VelocityProjection). Off by default: the midpoint step keeps
    // positions exactly inextensible without it and conserves energy to round-off
    // (measured |dE|/E ~ 1e-9 over 100 pendulum periods at T/100), whereas the
    // projection removes a little energy each step (O(h^3): ~1e-3 over the same run).
    // The projection after droplet capture is always done: it is the physical
    // impulsive tension response to an inelastic impact.
    bool projectVelocitiesAfterSubStep = false;
};

} // namespace dropletFiber
