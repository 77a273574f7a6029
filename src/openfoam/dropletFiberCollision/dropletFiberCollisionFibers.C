/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    Step 5 of execute(): the air at the fiber points and the fiber step. In
    parallel each processor advances its share of the fibers
    (fiberDistribution) and the states are exchanged afterwards.

\*---------------------------------------------------------------------------*/

#include "dropletFiberCollision.H"
#include "fiberDistribution.H"
#include "Pstream.H"

#include <stdexcept>
#include <string>
#include <vector>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- Points of a fiber in the air sample (FiberSolver::step samples movable
//  fibers only)
Eigen::Index sampledPoints(const ::dropletFiber::Fiber& fiber)
{
    return fiber.immobile() ? 0 : fiber.pointCount();
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

::dropletFiber::AirSample
Foam::functionObjects::dropletFiberCollision::sampleAir() const
{
    // The points of all movable fibers in fiber order, as FiberSolver::step
    // asks for them; identical on every processor, so the collective sample
    // is called by all or by none
    if (solverSettings_.drag.model == ::dropletFiber::DragModelType::none)
    {
        return {};
    }
    Eigen::Index n = 0;
    for (const auto& fiber : fibers_)
    {
        n += sampledPoints(fiber);
    }
    if (n == 0)
    {
        return {};
    }
    Eigen::Matrix3Xd points(3, n);
    n = 0;
    for (const auto& fiber : fibers_)
    {
        if (sampledPoints(fiber) > 0)
        {
            points.middleCols(n, fiber.pointCount()) = fiber.positions();
            n += fiber.pointCount();
        }
    }
    return air_->sample(points);
}


::dropletFiber::StepReport
Foam::functionObjects::dropletFiberCollision::advanceFibers
(
    const scalar dt,
    ::dropletFiber::CaptureSources& capture
)
{
    using namespace ::dropletFiber;
    const AirSample air = sampleAir();

    // This processor's fibers (all of them in a serial run), where their
    // points start in the air sample, and how many points they have there
    std::vector<std::size_t> mine;
    std::vector<Eigen::Index> mineFirstPoint;
    Eigen::Index first = 0, ownPoints = 0;
    for (std::size_t f = 0; f < fibers_.size(); ++f)
    {
        if (dropletFiber::fiberDistribution::advancesHere(f))
        {
            mine.push_back(f);
            mineFirstPoint.push_back(first);
            ownPoints += sampledPoints(fibers_[f]);
        }
        first += sampledPoints(fibers_[f]);
    }

    // Their slice of the air sample, their capture, and the fibers
    AirSample ownAir;
    if (air.velocity.cols() > 0)
    {
        ownAir.velocity.resize(3, ownPoints);
        ownAir.density.resize(ownPoints);
        ownAir.viscosity.resize(ownPoints);
    }
    std::vector<Fiber> own;
    CaptureSources ownCapture;
    own.reserve(mine.size());
    ownCapture.reserve(mine.size());
    Eigen::Index at = 0;
    for (std::size_t k = 0; k < mine.size(); ++k)
    {
        const std::size_t f = mine[k];
        if (air.velocity.cols() > 0)
        {
            const Eigen::Index n = sampledPoints(fibers_[f]);
            const Eigen::Index from = mineFirstPoint[k];
            ownAir.velocity.middleCols(at, n) = air.velocity.middleCols(from, n);
            ownAir.density.segment(at, n) = air.density.segment(from, n);
            ownAir.viscosity.segment(at, n) = air.viscosity.segment(from, n);
            at += n;
        }
        ownCapture.push_back(capture[f]);
        own.push_back(std::move(fibers_[f]));
    }
    const AirSampler sampler =
        [&ownAir](const Eigen::Matrix3Xd& points)
        {
            if (points.cols() != ownAir.velocity.cols())
            {
                throw std::logic_error
                (
                    "air sample of " + std::to_string(ownAir.velocity.cols())
                  + " points asked for " + std::to_string(points.cols())
                );
            }
            return ownAir;
        };

    StepReport report;
    std::string failure;
    try
    {
        report = solver_->step(own, dt, sampler, &ownCapture, &mine);
    }
    catch (const std::exception& e)
    {
        failure = e.what();
        if (failure.empty())
        {
            failure = "fiber step failed (no reason given)";
        }
    }
    for (std::size_t k = 0; k < mine.size(); ++k)
    {
        fibers_[mine[k]] = std::move(own[k]);
    }

    // The advanced fibers to every processor, with the processors' outcomes
    dropletFiber::fiberDistribution::stepOutcome outcome;
    outcome.failed = !failure.empty();
    outcome.maxSegmentLengthError = report.maxSegmentLengthError;
    outcome.subSteps = report.subSteps;
    outcome = dropletFiber::fiberDistribution::exchange
    (
        fibers_, capture, outcome
    );

    // A fiber that cannot be advanced even at the smallest sub-step stops
    // the run with the reason (the results written so far stay), on every
    // processor at once: all know from the exchange that one failed, so the
    // reasons are gathered only then
    if (outcome.failed)
    {
        List<string> failures(Pstream::nProcs());
        failures[Pstream::myProcNo()] = failure;
        Pstream::gatherList(failures);
        Pstream::scatterList(failures);
        for (const string& reason : failures)
        {
            if (!reason.empty())
            {
                FatalErrorInFunction
                    << type() << " " << name() << ": fiber step failed at time "
                    << time_.timeName() << ": " << reason.c_str() << nl
                    << "    Reduce the time step, or raise fibers.maxSubSteps ("
                    << solverSettings_.maxSubSteps << ")." << exit(FatalError);
            }
        }
    }

    // The figures the table and the log report, over all fibers
    report.maxSegmentLengthError = outcome.maxSegmentLengthError;
    report.subSteps = outcome.subSteps;
    return report;
}

// ************************************************************************* //
