#include "fiber/FiberSolver.hpp"

#include "fiber/FiberDiagnostics.hpp"
#include "fiber/VelocityProjection.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dropletFiber
{

FiberSolver::FiberSolver(const FiberSolverSettings& settings) : settings_(settings)
{
    auto fail = [](const std::string& what) { throw std::invalid_argument("FiberSolverSettings: " + what); };
    if (!(settings_.theta >= 0.5 && settings_.theta <= 1.0))
        fail("theta must be in [0.5, 1]");
    if (settings_.maxNewtonIterations < 1)
        fail("maxNewtonIterations must be >= 1");
    if (settings_.maxSubSteps < 1)
        fail("maxSubSteps must be >= 1");
    if (!(settings_.maxSegmentRotation > 0.0))
        fail("maxSegmentRotation must be > 0");
    if (!(settings_.maxDragStepRatio > 0.0))
        fail("maxDragStepRatio must be > 0");
    if (!(settings_.constraintTolerance > 0.0) || !(settings_.acceptableConstraintError > 0.0))
    {
        fail("tolerances must be > 0");
    }
    if (settings_.drag.model == DragModelType::linear
        && (settings_.drag.normalCoefficient < 0.0 || settings_.drag.tangentialCoefficient < 0.0))
    {
        fail("linear drag coefficients must be >= 0");
    }
}

void applyCapture(Fiber& fiber, const std::vector<SegmentSource>& sources)
{
    if (sources.empty())
        return;
    if (static_cast<Eigen::Index>(sources.size()) != fiber.segmentCount())
    {
        throw std::invalid_argument("capture: one SegmentSource per segment expected");
    }
    const Eigen::VectorXd massBefore = fiber.pointMasses();
    FiberState& state = fiber.mutableState();
    Eigen::Matrix3Xd pointMomentum = state.velocities * massBefore.asDiagonal();
    for (std::size_t j = 0; j < sources.size(); ++j)
    {
        const SegmentSource& source = sources[j];
        if (source.mass < 0.0)
            throw std::invalid_argument("capture: negative mass");
        const auto jj = static_cast<Eigen::Index>(j);
        state.segmentCapturedMass(jj) += source.mass;
        state.segmentHits(jj) += source.hits;
        state.segmentExpectedMass(jj) += source.expectedMass;
        pointMomentum.col(jj) += 0.5 * source.momentum;
        pointMomentum.col(jj + 1) += 0.5 * source.momentum;
    }
    const Eigen::VectorXd massAfter = fiber.pointMasses();
    for (Eigen::Index i = 0; i < fiber.pointCount(); ++i)
    {
        state.velocities.col(i) = pointMomentum.col(i) / massAfter(i);
    }
    projectVelocities(fiber);
}

void FiberSolver::updateDrag(const Fiber& fiber, const AirSample* air, Eigen::Index firstPoint)
{
    drag_.airVelocity = nullptr;
    if (air == nullptr)
        return;
    const Eigen::Index n = fiber.pointCount();
    airVelocity_ = air->velocity.middleCols(firstPoint, n);
    // The turbulent fluctuation joins the mean air (docs/model.md sec. 8); an all-zero
    // one (k = 0) is not added, so that it leaves every bit as without turbulence.
    const Eigen::Matrix3Xd& turbulent = fiber.state().turbulentVelocity;
    if (turbulent.cols() == n && !turbulent.isZero(0.0))
        airVelocity_ += turbulent;
    drag_.airVelocity = &airVelocity_;
    drag_.normal.resize(n);
    drag_.tangential.resize(n);
    const Eigen::Matrix3Xd& x = fiber.positions();
    const double radius = fiber.material().radius;
    const double logarithm = fiberLogarithm(radius, fiber.length());
    for (Eigen::Index i = 0; i < n; ++i)
    {
        const Eigen::Index hi = std::min(i + 1, n - 1), lo = std::max(i - 1, Eigen::Index(0));
        const Eigen::Vector3d t = (x.col(hi) - x.col(lo)).normalized();
        const Eigen::Vector3d w = airVelocity_.col(i) - fiber.velocities().col(i);
        const double normalSpeed = (w - t.dot(w) * t).norm();
        const DragCoefficients c
            = dragCoefficientsOfFiber(settings_.drag, air->density(firstPoint + i),
                                      air->viscosity(firstPoint + i), radius, logarithm, normalSpeed);
        drag_.normal(i) = c.normal;
        drag_.tangential(i) = c.tangential;
    }
}

void FiberSolver::advanceSpan(Fiber& fiber, std::size_t fiberIndex, double h, double hMin,
                              const AirSample* air, Eigen::Index firstPoint, StepReport& report,
                              int& acceptedSubSteps, bool dragIsCurrent)
{
    // One backup suffices for the recursion: a frame needs its own only until it
    // restores it, before it recurses.
    FiberState& state = fiber.mutableState();
    backupPositions_ = state.positions;
    backupVelocities_ = state.velocities;
    backupTension_ = state.tension;
    if (!dragIsCurrent)
        updateDrag(fiber, air, firstPoint);
    const SubStepResult result = implicitStep_.advance(fiber, h, drag_, settings_);
    report.newtonIterations += result.iterations;
    report.maxNewtonIterations = std::max(report.maxNewtonIterations, result.iterations);

    const bool canSplit = 0.5 * h >= hMin * (1.0 - 1e-9);
    const bool accurate = result.maxRotation <= settings_.maxSegmentRotation;
    if (result.converged && (accurate || !canSplit))
    {
        if (result.loose)
            ++report.looseConvergences;
        if (reaction_ != nullptr)
            implicitStep_.addDragImpulse(drag_, *reaction_, firstPoint);
        if (settings_.projectVelocitiesAfterSubStep)
            projectVelocities(fiber);
        ++acceptedSubSteps;
        return;
    }
    state.positions = backupPositions_;
    state.velocities = backupVelocities_;
    state.tension = backupTension_;
    if (!canSplit)
    {
        throw std::runtime_error("FiberSolver: fiber " + std::to_string(fiberIndex)
                                 + " did not converge at the smallest sub-step " + std::to_string(h)
                                 + " s (maxSubSteps = " + std::to_string(settings_.maxSubSteps) + ")");
    }
    ++report.rejectedSubSteps;
    advanceSpan(fiber, fiberIndex, 0.5 * h, hMin, air, firstPoint, report, acceptedSubSteps, true);
    advanceSpan(fiber, fiberIndex, 0.5 * h, hMin, air, firstPoint, report, acceptedSubSteps, false);
}

void FiberSolver::advanceFiber(Fiber& fiber, std::size_t fiberIndex, double dt, const AirSample* air,
                               Eigen::Index firstPoint, StepReport& report)
{
    // Split up front so each sub-step spans at most maxDragStepRatio relaxation times.
    updateDrag(fiber, air, firstPoint);
    int initialSplit = 1;
    if (air != nullptr)
    {
        const Eigen::VectorXd sigma = fiber.lineDensityAtPoints();
        double fastest = 0.0; // largest c_n / sigma = 1 / relaxation time
        for (Eigen::Index i = 0; i < fiber.pointCount(); ++i)
        {
            fastest = std::max(fastest, std::max(drag_.normal(i), drag_.tangential(i)) / sigma(i));
        }
        const double wanted = std::ceil(dt * fastest / settings_.maxDragStepRatio);
        initialSplit
            = static_cast<int>(std::min(std::max(wanted, 1.0), static_cast<double>(settings_.maxSubSteps)));
    }
    const double hMin = dt / settings_.maxSubSteps;
    int accepted = 0;
    for (int k = 0; k < initialSplit; ++k)
    {
        advanceSpan(fiber, fiberIndex, dt / initialSplit, hMin, air, firstPoint, report, accepted, k == 0);
    }
    report.subSteps += accepted;
    report.maxSubStepsOfAFiber = std::max(report.maxSubStepsOfAFiber, accepted);
}

const AirSample* FiberSolver::airForDrag(const AirSampleLayout& layout, const AirSample& air) const
{
    if (settings_.drag.model == DragModelType::none)
        return nullptr;
    const Eigen::Index pointTotal = layout.pointCount;
    if (pointTotal == 0)
        return nullptr;
    if (air.pointCount() != pointTotal || air.density.size() != pointTotal
        || air.viscosity.size() != pointTotal)
    {
        throw std::invalid_argument(
            "FiberSolver::step: drag needs the air at the " + std::to_string(pointTotal)
            + " points of airSamplePoints, the sample has " + std::to_string(air.pointCount()));
    }
    return &air;
}

void FiberSolver::addDiagnostics(const std::vector<Fiber>& fibers, StepReport& report) const
{
    for (const Fiber& fiber : fibers)
    {
        const FiberDiagnostics d = diagnose(fiber, settings_.gravity);
        report.kineticEnergy += d.kineticEnergy;
        report.elasticEnergy += d.elasticEnergy;
        report.gravitationalEnergy += d.gravitationalEnergy;
        report.totalMass += d.totalMass;
        report.totalCapturedMass += d.totalCapturedMass;
        report.momentum += d.momentum;
        report.maxSegmentLengthError = std::max(report.maxSegmentLengthError, d.maxSegmentLengthError);
    }
}

StepReport FiberSolver::step(std::vector<Fiber>& fibers, double dt, const AirSample& air,
                             const CaptureSources* capture, const std::vector<std::size_t>* fiberNumbers,
                             DragReaction* reaction)
{
    if (!(dt > 0.0))
        throw std::invalid_argument("FiberSolver::step: dt must be > 0");
    if (capture != nullptr && capture->size() != fibers.size())
    {
        throw std::invalid_argument("FiberSolver::step: capture needs one list per fiber");
    }
    if (fiberNumbers != nullptr && fiberNumbers->size() != fibers.size())
    {
        throw std::invalid_argument("FiberSolver::step: fiberNumbers needs one number per fiber");
    }
    StepReport report;

    if (capture != nullptr)
    {
        for (std::size_t f = 0; f < fibers.size(); ++f)
        {
            applyCapture(fibers[f], (*capture)[f]);
        }
    }

    const AirSampleLayout layout = airSampleLayout(fibers);
    const AirSample* airPointer = airForDrag(layout, air);
    if (reaction != nullptr)
        reaction->reset(layout.pointCount);
    reaction_ = airPointer != nullptr ? reaction : nullptr;
    for (std::size_t f = 0; f < fibers.size(); ++f)
    {
        if (fibers[f].immobile())
            continue;
        advanceFiber(fibers[f], fiberNumbers != nullptr ? (*fiberNumbers)[f] : f, dt, airPointer,
                     layout.firstPoint[f], report);
        ++report.fibersAdvanced;
    }

    reaction_ = nullptr;
    addDiagnostics(fibers, report);
    return report;
}

} // namespace dropletFiber
