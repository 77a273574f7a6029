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

#include <exception>
#include <string>
#include <vector>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

::dropletFiber::AirSample
Foam::functionObjects::dropletFiberCollision::sampleAir() const
{
    // The points the core lays out (all movable fibers, AirSample.hpp);
    // identical on every processor, so the collective sample is called by
    // all or by none
    if (solverSettings_.drag.model == ::dropletFiber::DragModelType::none)
    {
        return {};
    }
    const Eigen::Matrix3Xd points = ::dropletFiber::airSamplePoints(fibers_);
    if (points.cols() == 0)
    {
        return {};
    }
    const ::dropletFiber::AirSample air = air_->sample(points, parallelStatistics_);
    stopIfAirNotFinite(air);
    return air;
}


void Foam::functionObjects::dropletFiberCollision::stopIfAirNotFinite
(
    const ::dropletFiber::AirSample& air
) const
{
    // The same sample on every processor: all stop, with the same message
    string quantity;
    const label p = air_->firstNonFinite(air, quantity);
    if (p < 0 && air_->nonFiniteVelocityCells() == 0)
    {
        return;
    }
    if (p < 0)
    {
        FatalErrorInFunction
            << type() << " " << name() << ": the air velocity is not finite"
            << " in " << air_->nonFiniteVelocityCells() << " cells or"
            << " boundary faces at time " << time_.timeName()
            << " (at no fiber point)." << nl
            << "    The flow has diverged: the fibers cannot be advanced in"
            << " it." << exit(FatalError);
    }
    const ::dropletFiber::AirSampleLayout layout =
        ::dropletFiber::airSampleLayout(fibers_);
    std::size_t f = 0;
    while
    (
        p >= layout.firstPoint[f]
           + ::dropletFiber::airSamplePointCount(fibers_[f])
    )
    {
        ++f;   // p is a point of a later fiber (immobile ones have none)
    }
    const label i = p - label(layout.firstPoint[f]);
    const Eigen::Vector3d x = fibers_[f].positions().col(i);
    FatalErrorInFunction
        << type() << " " << name() << ": the air " << quantity.c_str()
        << " is not finite at time " << time_.timeName() << " at point " << i
        << " (" << x.x() << ' ' << x.y() << ' ' << x.z() << ") of fiber " << f
        << " (from '" << fiberOrigin_[f] << "')." << nl
        << "    The flow has diverged there (or the field holds nan/inf):"
        << " the fibers cannot be advanced in it." << exit(FatalError);
}


std::vector<std::size_t>
Foam::functionObjects::dropletFiberCollision::fibersAdvancedHere() const
{
    std::vector<std::size_t> mine;
    for (std::size_t f = 0; f < fibers_.size(); ++f)
    {
        if (dropletFiber::fiberDistribution::advancesHere(f))
        {
            mine.push_back(f);
        }
    }
    return mine;
}


std::string Foam::functionObjects::dropletFiberCollision::stepFibers
(
    const std::vector<std::size_t>& mine,
    const scalar dt,
    const ::dropletFiber::AirSample& air,
    const ::dropletFiber::CaptureSources& capture,
    ::dropletFiber::StepReport& report
)
{
    // The fibers leave the list for the step (the solver steps a list of its
    // own) and come back afterwards, failed or not
    const ::dropletFiber::AirSample ownAir =
        ::dropletFiber::airSampleOfFibers(air, fibers_, mine);
    std::vector<::dropletFiber::Fiber> own;
    ::dropletFiber::CaptureSources ownCapture;
    own.reserve(mine.size());
    ownCapture.reserve(mine.size());
    for (const std::size_t f : mine)
    {
        ownCapture.push_back(capture[f]);
        own.push_back(std::move(fibers_[f]));
    }

    std::string failure;
    try
    {
        report = solver_->step(own, dt, ownAir, &ownCapture, &mine);
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
    return failure;
}


void Foam::functionObjects::dropletFiberCollision::stopIfStepFailed
(
    const bool anyFailed,
    const std::string& failure
) const
{
    // On every processor at once: all know from the exchange that one
    // failed, so the reasons are gathered only then
    if (!anyFailed)
    {
        return;
    }
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


::dropletFiber::StepReport
Foam::functionObjects::dropletFiberCollision::advanceFibers
(
    const scalar dt,
    ::dropletFiber::CaptureSources& capture
)
{
    const ::dropletFiber::AirSample air = sampleAir();
    const std::vector<std::size_t> mine = fibersAdvancedHere();
    ::dropletFiber::StepReport report;
    const std::string failure = stepFibers(mine, dt, air, capture, report);

    // The advanced fibers to every processor, with the processors' outcomes
    dropletFiber::fiberDistribution::stepOutcome outcome;
    outcome.failed = !failure.empty();
    outcome.maxSegmentLengthError = report.maxSegmentLengthError;
    outcome.subSteps = report.subSteps;
    outcome = dropletFiber::fiberDistribution::exchange
    (
        fibers_, capture, outcome, parallelStatistics_
    );

    // A fiber that cannot be advanced even at the smallest sub-step stops
    // the run with the reason (the results written so far stay)
    stopIfStepFailed(outcome.failed, failure);

    // The figures the table and the log report, over all fibers
    report.maxSegmentLengthError = outcome.maxSegmentLengthError;
    report.subSteps = outcome.subSteps;
    return report;
}

// ************************************************************************* //
