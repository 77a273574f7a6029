/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    Step 5 of execute(): the air at the fiber points and the fiber step. In
    parallel each processor advances the fibers it holds (fiberOwnership),
    with the air at their points (airSampler asks the processors holding
    the points outside its cells); the outcome is reduced as scalars.

\*---------------------------------------------------------------------------*/

#include "dropletFiberCollision.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"
#include "OStringStream.H"

#include <exception>
#include <string>
#include <vector>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

::dropletFiber::AirSample
Foam::functionObjects::dropletFiberCollision::sampleAir
(
    ::dropletFiber::TurbulenceSample* turbulence
) const
{
    // The points the core lays out (the movable fibers held here,
    // AirSample.hpp). Collective: every processor samples, with its points
    // or none, unless no processor has any
    if (solverSettings_.drag.model == ::dropletFiber::DragModelType::none)
    {
        return {};
    }
    const Eigen::Matrix3Xd points = ::dropletFiber::airSamplePoints(held_.fibers);
    if (returnReduce(label(points.cols()), sumOp<label>()) == 0)
    {
        return {};
    }
    const ::dropletFiber::AirSample air =
        air_->sample(points, *boxes_, parallelStatistics_, turbulence);
    stopIfAirNotFinite(air);
    return air;
}


Foam::string Foam::functionObjects::dropletFiberCollision::nonFiniteAirHere
(
    const ::dropletFiber::AirSample& air
) const
{
    string quantity;
    const label p = air_->firstNonFinite(air, quantity);
    if (p < 0)
    {
        return string();
    }
    const std::vector<::dropletFiber::Fiber>& fibers = held_.fibers;
    const ::dropletFiber::AirSampleLayout layout =
        ::dropletFiber::airSampleLayout(fibers);
    std::size_t f = 0;
    while
    (
        p >= layout.firstPoint[f]
           + ::dropletFiber::airSamplePointCount(fibers[f])
    )
    {
        ++f;   // p is a point of a later fiber (immobile ones have none)
    }
    const label i = p - label(layout.firstPoint[f]);
    const Eigen::Vector3d x = fibers[f].positions().col(i);
    OStringStream os;
    os  << "the air " << quantity.c_str()
        << " is not finite at time " << time_.timeName() << " at point " << i
        << " (" << x.x() << ' ' << x.y() << ' ' << x.z() << ") of fiber "
        << held_.id[f] << " (from '" << held_.origin[f] << "').";
    return os.str();
}


Foam::string Foam::functionObjects::dropletFiberCollision::firstFailureOfAll
(
    const string& failure
)
{
    if (!returnReduce(!failure.empty(), orOp<bool>()))
    {
        return string();
    }
    List<string> failures(Pstream::nProcs());
    failures[Pstream::myProcNo()] = failure;
    Pstream::gatherList(failures);
    Pstream::scatterList(failures);
    for (const string& reason : failures)
    {
        if (!reason.empty())
        {
            return reason;
        }
    }
    return string();
}


void Foam::functionObjects::dropletFiberCollision::stopIfAirNotFinite
(
    const ::dropletFiber::AirSample& air
) const
{
    // Each processor checks the air of its own fibers; all stop, with the
    // message of the first processor that found one
    const string failure = firstFailureOfAll(nonFiniteAirHere(air));
    if (failure.empty() && air_->nonFiniteVelocityCells() == 0)
    {
        return;
    }
    if (failure.empty())
    {
        FatalErrorInFunction
            << type() << " " << name() << ": the air velocity is not finite"
            << " in " << air_->nonFiniteVelocityCells() << " cells or"
            << " boundary faces at time " << time_.timeName()
            << " (at no fiber point)." << nl
            << "    The flow has diverged: the fibers cannot be advanced in"
            << " it." << exit(FatalError);
    }
    FatalErrorInFunction
        << type() << " " << name() << ": " << failure.c_str() << nl
        << "    The flow has diverged there (or the field holds nan/inf):"
        << " the fibers cannot be advanced in it." << exit(FatalError);
}


std::string Foam::functionObjects::dropletFiberCollision::stepFibers
(
    const scalar dt,
    const ::dropletFiber::AirSample& air,
    const ::dropletFiber::CaptureSources& capture,
    ::dropletFiber::StepReport& report
)
{
    // The solver's messages name the fibers by their ids
    const std::vector<std::size_t> ids(held_.id.begin(), held_.id.end());
    std::string failure;
    try
    {
        report = solver_->step(held_.fibers, dt, air, &capture, &ids);
    }
    catch (const std::exception& e)
    {
        failure = e.what();
        if (failure.empty())
        {
            failure = "fiber step failed (no reason given)";
        }
    }
    return failure;
}


void Foam::functionObjects::dropletFiberCollision::stopIfStepFailed
(
    const std::string& failure
) const
{
    const string reason = firstFailureOfAll(failure);
    if (!reason.empty())
    {
        FatalErrorInFunction
            << type() << " " << name() << ": fiber step failed at time "
            << time_.timeName() << ": " << reason.c_str() << nl
            << "    Reduce the time step, or raise fibers.maxSubSteps ("
            << solverSettings_.maxSubSteps << ")." << exit(FatalError);
    }
}


::dropletFiber::StepReport
Foam::functionObjects::dropletFiberCollision::advanceFibers
(
    const scalar dt,
    ::dropletFiber::CaptureSources& capture
)
{
    // With turbulent air the fluctuation u' of every point is advanced
    // first, from the k and epsilon sampled with the air
    const bool turbulent =
        turbulence_.settings.model != ::dropletFiber::TurbulenceModelType::none;
    ::dropletFiber::TurbulenceSample turbulence;
    const ::dropletFiber::AirSample air =
        sampleAir(turbulent ? &turbulence : nullptr);
    if (turbulent)
    {
        advanceTurbulence(dt, turbulence);
    }
    else
    {
        // Switched to none during the run or restarted with none from a
        // turbulent state: the mean air only, as without turbulence
        ::dropletFiber::clearTurbulentVelocities(held_.fibers);
    }
    // The step's own computing timed (the reductions after it are not)
    using stage = dropletFiber::parallelStatistics::stage;
    ::dropletFiber::StepReport report;
    std::string failure;
    parallelStatistics_.timed
    (
        stage::fibers,
        [&]() { failure = stepFibers(dt, air, capture, report); }
    );
    std::size_t points = 0;
    for (const ::dropletFiber::Fiber& fiber : held_.fibers)
    {
        points += std::size_t(fiber.pointCount());
    }
    parallelStatistics_.countFiberPoints(points);

    // A fiber that cannot be advanced even at the smallest sub-step stops
    // the run with the reason (the results written so far stay)
    stopIfStepFailed(failure);

    // The figures the table and the log report, over all fibers
    report.maxSegmentLengthError =
        returnReduce(report.maxSegmentLengthError, maxOp<scalar>());
    report.subSteps = int(returnReduce(label(report.subSteps), sumOp<label>()));
    return report;
}

// ************************************************************************* //
