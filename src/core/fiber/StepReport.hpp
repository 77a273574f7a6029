// StepReport: what one FiberSolver::step did, for logging by the caller (the core
// never prints). Energies and momentum are totals over all fibers after the step.
#pragma once

#include <Eigen/Core>

namespace dropletFiber
{

struct StepReport
{
    int fibersAdvanced = 0; // movable fibers stepped
    int subSteps = 0;       // accepted sub-steps, summed over fibers
    int maxSubStepsOfAFiber = 0;
    int rejectedSubSteps = 0;    // attempts that were halved (Newton failure/rotation)
    int newtonIterations = 0;    // linear solves, summed over all sub-steps
    int maxNewtonIterations = 0; // most linear solves in one sub-step
    int looseConvergences = 0;   // sub-steps accepted at acceptableConstraintError

    double maxSegmentLengthError = 0.0;                 // relative, all fibers, after the step
    double kineticEnergy = 0.0;                         // [J]
    double elasticEnergy = 0.0;                         // bending [J]
    double gravitationalEnergy = 0.0;                   // -m g.x, zero at the origin [J]
    double totalMass = 0.0;                             // [kg], fibers incl. captured droplets
    double totalCapturedMass = 0.0;                     // [kg]
    Eigen::Vector3d momentum = Eigen::Vector3d::Zero(); // [kg m/s]
};

} // namespace dropletFiber
