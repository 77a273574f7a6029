// FiberSolver: advances all fibers by one CFD time step (docs/model.md sec. 1).
// Per step, in this order:
//   1. droplet capture (optional): each segment's captured mass joins its two end
//      points (half each) with the droplets' momentum - an inelastic merge that
//      conserves momentum - followed by the impulsive tension response (velocity
//      projection) that keeps the fiber inextensible;
//   2. the air at all points of all movable fibers, sampled by the caller in one
//      batch before the step (see AirSample; not used when the drag model is none),
//      plus each point's turbulent fluctuation FiberState::turbulentVelocity when the
//      fiber has one (advanced by the caller before the step: TurbulentAir);
//   3. each movable fiber independently: implicit sub-steps (ImplicitFiberStep),
//      as many as its own accuracy needs (see FiberSolverSettings).
// Fibers are processed one after another in list order; no randomness, no threads:
// identical results on every MPI rank. The solver keeps no state between steps
// besides its settings and reusable work storage, so a restart from saved
// FiberStates is bit-for-bit identical.
#pragma once

#include "fiber/AirSample.hpp"
#include "fiber/Fiber.hpp"
#include "fiber/FiberSolverSettings.hpp"
#include "fiber/ImplicitFiberStep.hpp"
#include "fiber/SegmentSource.hpp"
#include "fiber/StepReport.hpp"

#include <vector>

namespace dropletFiber
{

class FiberSolver
{
public:
    explicit FiberSolver(const FiberSolverSettings& settings = FiberSolverSettings());

    const FiberSolverSettings& settings() const { return settings_; }

    // air: the air at airSamplePoints(fibers) (AirSample.hpp); may be empty when the
    // drag model is none or no fiber is movable.
    // capture: nullptr, or one list per fiber (empty, or one SegmentSource per segment).
    // Throws std::invalid_argument on inconsistent input and std::runtime_error when
    // a fiber cannot be advanced even at the smallest allowed sub-step.
    // fiberNumbers: nullptr, or the number of each fiber in the messages (a caller that
    // steps a subset of its fibers names them by their place in the whole list).
    // reaction: nullptr, or where the drag over the step goes, per point of the air
    // sample (DragReaction.hpp; reset here): the impulse of the accepted sub-steps'
    // drag at their converged iterates, which is what changed the fibers' momentum.
    StepReport step(std::vector<Fiber>& fibers, double dt, const AirSample& air,
                    const CaptureSources* capture = nullptr,
                    const std::vector<std::size_t>* fiberNumbers = nullptr, DragReaction* reaction = nullptr);

private:
    // The sample the drag uses (nullptr: no drag); checks it fits the fibers' layout.
    const AirSample* airForDrag(const AirSampleLayout& layout, const AirSample& air) const;
    // Energies, mass, momentum and constraint error of all fibers into report.
    void addDiagnostics(const std::vector<Fiber>& fibers, StepReport& report) const;
    void advanceFiber(Fiber& fiber, std::size_t fiberIndex, double dt, const AirSample* air,
                      Eigen::Index firstPoint, StepReport& report);
    // dragIsCurrent: drag_ was evaluated for the fiber's present state (saves doing
    // it again for the first sub-step and after a rejected one).
    void advanceSpan(Fiber& fiber, std::size_t fiberIndex, double h, double hMin, const AirSample* air,
                     Eigen::Index firstPoint, StepReport& report, int& acceptedSubSteps, bool dragIsCurrent);
    // Drag coefficients at the fiber's present state into drag_ (no drag: air null).
    void updateDrag(const Fiber& fiber, const AirSample* air, Eigen::Index firstPoint);

    FiberSolverSettings settings_;
    ImplicitFiberStep implicitStep_;
    // Where the step's drag goes (nullptr: nowhere), during step() only.
    DragReaction* reaction_ = nullptr;

    // Work storage reused between sub-steps and fibers (resized only when the point
    // count changes).
    Eigen::Matrix3Xd airVelocity_;
    PointDrag drag_;
    // State at the start of the sub-step being tried (what advance and the velocity
    // projection change), for a rejected sub-step.
    Eigen::Matrix3Xd backupPositions_, backupVelocities_;
    Eigen::VectorXd backupTension_;
};

// Inelastic capture on one fiber (step 1 above); exposed for tests and tools.
void applyCapture(Fiber& fiber, const std::vector<SegmentSource>& sources);

} // namespace dropletFiber
