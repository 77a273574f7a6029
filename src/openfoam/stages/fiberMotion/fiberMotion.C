/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The air at the fiber points and the fiber step. In
    parallel each processor advances the fibers it holds (fiberOwnership),
    with the air at their points (airSampler asks the processors holding
    the points outside its cells); the outcome is reduced as scalars.

\*---------------------------------------------------------------------------*/

#include "fiberMotion.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"
#include "OStringStream.H"
#include "plausibility.H"

#include <exception>
#include <string>
#include <vector>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

::dropletFiber::AirSample
Foam::dropletFiber::fiberMotion::sampleAir
(
    const heldFibers& held,
    const processorBoxes& boxes,
    parallelStatistics& statistics,
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
    const Eigen::Matrix3Xd points = ::dropletFiber::airSamplePoints(held.fibers);
    if (returnReduce(label(points.cols()), sumOp<label>()) == 0)
    {
        return {};
    }
    const ::dropletFiber::AirSample air =
        air_->sample(points, boxes, statistics, turbulence);
    stopIfAirNotFinite(held, air);
    return air;
}


Foam::string Foam::dropletFiber::fiberMotion::nonFiniteAirHere
(
    const heldFibers& held,
    const ::dropletFiber::AirSample& air
) const
{
    string quantity;
    const label p = air_->firstNonFinite(air, quantity);
    if (p < 0)
    {
        return string();
    }
    const std::vector<::dropletFiber::Fiber>& fibers = held.fibers;
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
        << held.id[f] << " (from '" << held.origin[f] << "').";
    return os.str();
}


Foam::string Foam::dropletFiber::fiberMotion::firstFailureOfAll
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


void Foam::dropletFiber::fiberMotion::stopIfAirNotFinite
(
    const heldFibers& held,
    const ::dropletFiber::AirSample& air
) const
{
    // Each processor checks the air of its own fibers; all stop, with the
    // message of the first processor that found one
    const string failure = firstFailureOfAll(nonFiniteAirHere(held, air));
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


std::string Foam::dropletFiber::fiberMotion::stepFibers
(
    heldFibers& held,
    const scalar dt,
    const ::dropletFiber::AirSample& air,
    const ::dropletFiber::CaptureSources& capture,
    ::dropletFiber::StepReport& report,
    const bool reaction
)
{
    // The solver's messages name the fibers by their ids
    const std::vector<std::size_t> ids(held.id.begin(), held.id.end());
    std::string failure;
    try
    {
        report = solver_->step
        (
            held.fibers, dt, air, &capture, &ids,
            reaction ? &dragReaction_ : nullptr
        );
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


void Foam::dropletFiber::fiberMotion::stopIfStepFailed
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
Foam::dropletFiber::fiberMotion::advanceFibers
(
    heldFibers& held,
    const processorBoxes& boxes,
    const scalar dt,
    ::dropletFiber::CaptureSources& capture,
    parallelStatistics& statistics,
    airReaction& reaction
)
{
    // With turbulent air the fluctuation u' of every point is advanced
    // first, from the k and epsilon sampled with the air
    const bool turbulent = this->turbulent();
    ::dropletFiber::TurbulenceSample turbulence;
    const ::dropletFiber::AirSample air =
        sampleAir(held, boxes, statistics, turbulent ? &turbulence : nullptr);
    if (turbulent)
    {
        advanceTurbulence(held, dt, turbulence);
    }
    else
    {
        // Switched to none during the run or restarted with none from a
        // turbulent state: the mean air only, as without turbulence
        ::dropletFiber::clearTurbulentVelocities(held.fibers);
    }
    // The step's own computing timed (the reductions after it are not)
    using stage = parallelStatistics::stage;
    ::dropletFiber::StepReport report;
    std::string failure;
    statistics.timed
    (
        stage::fibers,
        [&]()
        {
            failure =
                stepFibers(held, dt, air, capture, report, reaction.wanted());
        }
    );
    std::size_t points = 0;
    for (const ::dropletFiber::Fiber& fiber : held.fibers)
    {
        points += std::size_t(fiber.pointCount());
    }
    statistics.countFiberPoints(points);

    // A fiber that cannot be advanced even at the smallest sub-step stops
    // the run with the reason (the results written so far stay)
    stopIfStepFailed(failure);
    if (reaction.wanted())
    {
        reaction.startStep();
        const bool sampled =
            returnReduce(label(air.pointCount()), sumOp<label>()) > 0;
        handMovingDrag(held, sampled, dt, reaction, statistics);
        if (reaction.coupled())
        {
            handImmobileDrag(held, boxes, reaction, statistics);
        }
        reaction.finishStep(air_->velocity(), air_->referenceDensity());
    }

    // The figures the table and the log report, over all fibers
    report.maxSegmentLengthError =
        returnReduce(report.maxSegmentLengthError, maxOp<scalar>());
    report.subSteps = int(returnReduce(label(report.subSteps), sumOp<label>()));
    return report;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dropletFiber::fiberMotion::fiberMotion
(
    const functionObject& owner,
    const fvMesh& mesh
)
:
    couplingStage(owner, mesh),
    warnedZeroK_(false)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dropletFiber::fiberMotion::read
(
    const dictionary& airDict,
    const dictionary& fibersDict,
    const bool running
)
{
    air_.reset(new airSampler(mesh_, airDict));
    immobileAir_.reset(new airSampler(mesh_, airDict));
    solverSettings_ = readFiberSolverSettings(fibersDict, time_);
    solver_.reset(new ::dropletFiber::FiberSolver(solverSettings_));
    turbulence_ = readFiberTurbulence(fibersDict, mesh_);
    if (!running)
    {
        // Unit slips run, warned once at the start
        warnImplausibleFibers(fibersDict);
        warnImplausibleAir(airDict);
    }
}


::dropletFiber::StepReport Foam::dropletFiber::fiberMotion::advance
(
    heldFibers& held,
    const processorBoxes& boxes,
    const scalar dt,
    ::dropletFiber::CaptureSources& capture,
    parallelStatistics& statistics,
    airReaction& reaction
)
{
    lastStep_ = coreCall
    (
        "advancing the fibers",
        [&]()
        {
            return
                advanceFibers(held, boxes, dt, capture, statistics, reaction);
        }
    );
    return lastStep_;
}


void Foam::dropletFiber::fiberMotion::addStepFigures(stepFigures& step) const
{
    step.add("maxSegmentLengthError", lastStep_.maxSegmentLengthError);
    step.addCount("subSteps", lastStep_.subSteps);
}


void Foam::dropletFiber::fiberMotion::reportAir(Ostream& os) const
{
    air_->report(os);
}


void Foam::dropletFiber::fiberMotion::report
(
    Ostream& os,
    const label injectors,
    const label fibers
) const
{
    const auto& s = solverSettings_;
    os  << "    fibers: gravity (" << s.gravity.x() << ' ' << s.gravity.y() << ' '
        << s.gravity.z() << "), drag "
        << ::dropletFiber::dragModelName(s.drag.model).c_str()
        << ", theta " << s.theta << ", injectors " << injectors
        << ", fibers now " << fibers << nl;
    reportTurbulence(os);
}


//- The function object's entries the motion reads (their own: airSampler.C, fiberSettings.C)
static const Foam::wordList motionKeys
{
    "air", "fibers"
};


Foam::wordList Foam::dropletFiber::fiberMotion::entries()
{
    return motionKeys;
}


// ************************************************************************* //
