// FiberDiagnostics: energies, mass, momentum and constraint error of one fiber
// (docs/model.md sec. 1 bookkeeping; summed into StepReport by the solver).
#pragma once

#include "fiber/Fiber.hpp"

namespace dropletFiber
{

struct FiberDiagnostics
{
    double kineticEnergy = 0.0;
    double elasticEnergy = 0.0;
    double gravitationalEnergy = 0.0;
    double totalMass = 0.0;
    double totalCapturedMass = 0.0;
    Eigen::Vector3d momentum = Eigen::Vector3d::Zero();
    Eigen::Vector3d centreOfMass = Eigen::Vector3d::Zero();
    double maxSegmentLengthError = 0.0;

    double totalEnergy() const { return kineticEnergy + elasticEnergy + gravitationalEnergy; }
};

FiberDiagnostics diagnose(const Fiber& fiber, const Eigen::Vector3d& gravity);

} // namespace dropletFiber
