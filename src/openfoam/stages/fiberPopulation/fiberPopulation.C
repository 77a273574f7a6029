/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The fibers born, lost and handed over, and the sums over all of them.

\*---------------------------------------------------------------------------*/

#include "fiberPopulation.H"
#include "fiberMotion.H"
#include "dictionaryChecks.H"
#include "PstreamReduceOps.H"
#include "OStringStream.H"

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

Foam::point toPoint(const Eigen::Vector3d& x)
{
    return Foam::point(x.x(), x.y(), x.z());
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dropletFiber::fiberPopulation::fiberPopulation
(
    const functionObject& owner,
    const fvMesh& mesh
)
:
    couplingStage(owner, mesh),
    nextFiberId_(0),
    holders_(fiberOwnership::holderRule::cells),
    clock_(0),
    clockIndex_(-1)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::dropletFiber::fiberPopulation::continuousTime()
{
    // deltaT added as Time::operator++ adds it, one step at a time
    while (clockIndex_ >= 0 && clockIndex_ < time_.timeIndex())
    {
        clock_ += time_.deltaTValue();
        ++clockIndex_;
    }
    if
    (
        clockIndex_ != time_.timeIndex()
     || mag(clock_ - time_.value()) > 1e-9*time_.deltaTValue()
    )
    {
        // A fresh run, or a time changed by hand: OpenFOAM's own
        clock_ = time_.value();
        clockIndex_ = time_.timeIndex();
    }
    return clock_;
}


void Foam::dropletFiber::fiberPopulation::injectFibers
(
    const scalar t,
    parallelStatistics& statistics
)
{
    // Every processor advances every injector alike (cheap) and keeps the
    // fibers born in its cells
    heldFibers born;
    for (auto& injector : injectors_)
    {
        std::vector<::dropletFiber::Fiber> fibers;
        try
        {
            fibers = injector.inject(t);
        }
        catch (const std::exception& e)
        {
            // A count beyond what a double holds exactly (a rate of ~1e12
            // per second for hours): no run could hold those fibers anyway
            FatalErrorInFunction
                << type() << " " << name() << ": cannot inject fibers at time "
                << time_.timeName() << ": " << e.what() << exit(FatalError);
        }
        for (auto& fiber : fibers)
        {
            born.append(std::move(fiber), injector.spec().name, nextFiberId_++);
        }
    }
    takeBornFibers(born, statistics);
}


void Foam::dropletFiber::fiberPopulation::takeBornFibers
(
    heldFibers& born,
    parallelStatistics& statistics
)
{
    // All processors have all of them: the mass is added alike everywhere,
    // in the order of birth (a serial run's)
    for (const auto& fiber : born.fibers)
    {
        totals_.massAdded += fiber.represents()*fiber.totalMass();
    }
    fiberOwnership::keepBornHere(*boxes_, born, statistics, holders_);
    for (std::size_t k = 0; k < born.size(); ++k)
    {
        held_.append(std::move(born.fibers[k]), born.origin[k], born.id[k]);
    }
}


void Foam::dropletFiber::fiberPopulation::removeLostFibers()
{
    // The running totals go on from the master's; the others' removals are
    // added to it (a serial run adds them one after another, as always)
    const boundBox& box = mesh_.bounds();
    scalar massRemoved = Pstream::master() ? totals_.massRemoved : 0;
    scalar binderRemoved = Pstream::master() ? totals_.binderRemoved : 0;
    label removed = 0;
    held_.keepIf
    (
        [&](std::size_t f)
        {
            const ::dropletFiber::Fiber& fiber = held_.fibers[f];
            const Eigen::Matrix3Xd& x = fiber.positions();
            for (Eigen::Index i = 0; i < x.cols(); ++i)
            {
                if (box.contains(point(x(0, i), x(1, i), x(2, i))))
                {
                    return true;
                }
            }
            massRemoved += fiber.represents()*fiber.totalMass();
            binderRemoved += fiber.represents()*fiber.totalCapturedMass();
            ++removed;
            return false;
        }
    );
    totals_.massRemoved = returnReduce(massRemoved, sumOp<scalar>());
    totals_.binderRemoved = returnReduce(binderRemoved, sumOp<scalar>());
    totals_.removed += returnReduce(removed, sumOp<label>());
}


::dropletFiber::StepReport Foam::dropletFiber::fiberPopulation::advance
(
    fiberMotion& motion,
    const scalar dt,
    ::dropletFiber::CaptureSources& capture,
    parallelStatistics& statistics,
    airReaction& reaction
)
{
    return motion.advance(held_, *boxes_, dt, capture, statistics, reaction);
}


void Foam::dropletFiber::fiberPopulation::notePopulationSpreads
(
    const std::unordered_map<label, scalar>& spreadById
)
{
    if (spreadById.empty())
    {
        return;
    }
    for (std::size_t f = 0; f < held_.size(); ++f)
    {
        const auto found = spreadById.find(held_.id[f]);
        if (found != spreadById.end())
        {
            held_.fibers[f].setPopulationSpread(found->second);
        }
    }
}


void Foam::dropletFiber::fiberPopulation::removeLaid(const labelList& laid)
{
    // The totals go on from the master's, the others' added to it, as the
    // fibers lost (removeLostFibers)
    scalar glass = Pstream::master() ? totals_.glassLaid : 0;
    scalar binder = Pstream::master() ? totals_.binderLaid : 0;
    label taken = 0;
    if (!laid.empty())
    {
        held_.keepIf
        (
            [&](std::size_t f)
            {
                if (taken < laid.size() && laid[taken] == label(f))
                {
                    const ::dropletFiber::Fiber& fiber = held_.fibers[f];
                    const scalar n = fiber.represents();
                    const scalar b = fiber.totalCapturedMass();
                    glass += n*(fiber.totalMass() - b);
                    binder += n*b;
                    ++taken;
                    return false;
                }
                return true;
            }
        );
    }
    totals_.glassLaid = returnReduce(glass, sumOp<scalar>());
    totals_.binderLaid = returnReduce(binder, sumOp<scalar>());
    totals_.laid += returnReduce(taken, sumOp<label>());
}


Foam::wordList Foam::dropletFiber::fiberPopulation::stepColumns() const
{
    wordList columns{"fibers", "fiberMass"};
    if (weighted())
    {
        columns.append("fibersRepresented");
    }
    return columns;
}


void Foam::dropletFiber::fiberPopulation::addStepFigures
(
    stepFigures& step
) const
{
    step.addCount("fibers", count());
    if (weighted())
    {
        step.add("fibersRepresented", represented());
    }
    step.add("fiberMass", mass());
}


void Foam::dropletFiber::fiberPopulation::reportConservation
(
    const scalar captured
) const
{
    const scalar fiberMass = mass();
    const fiberTotals& t = totals_;
    const scalar laid = t.glassLaid + t.binderLaid;
    Info<< "    fiber mass " << fiberMass << " kg = added " << t.massAdded
        << " + captured " << captured << " - removed " << t.massRemoved;
    if (t.countBinderRemoved)
    {
        Info<< " - laid " << laid;
    }
    Info<< " (balance "
        << t.massAdded + captured - t.massRemoved - laid - fiberMass
        << " kg)" << endl;
}


void Foam::dropletFiber::fiberPopulation::reportBalanceAtWrite
(
    const scalar captured
) const
{
    if (!totals_.countBinderRemoved)
    {
        return;
    }
    const fiberTotals& t = totals_;
    const scalar binderInAir = binderSums().values[2];
    const scalar glassInAir = mass() - binderInAir;
    const scalar glassLost = t.massRemoved - t.binderRemoved;
    Info<< "    glass: injected " << t.massAdded << " kg = in the air "
        << glassInAir << " + laid " << t.glassLaid << " + lost " << glassLost
        << " (balance "
        << t.massAdded - glassInAir - t.glassLaid - glassLost << " kg)" << nl
        << "    binder: captured " << captured << " kg = on airborne fibers "
        << binderInAir << " + laid " << t.binderLaid << " + on lost fibers "
        << t.binderRemoved << " (balance "
        << captured - binderInAir - t.binderLaid - t.binderRemoved << " kg)"
        << nl;
}


Foam::boolList Foam::dropletFiber::fiberPopulation::insideMesh
(
    const List<point>& points
) const
{
    // Found on any processor
    labelList found(points.size(), 0);
    forAll(points, i)
    {
        found[i] = mesh_.findCell(points[i]) >= 0 ? 1 : 0;
    }
    Pstream::listCombineGather(found, maxEqOp<label>());
    Pstream::listCombineScatter(found);
    boolList inside(points.size());
    forAll(found, i)
    {
        inside[i] = found[i] > 0;
    }
    return inside;
}


void Foam::dropletFiber::fiberPopulation::warnPointsOutside
(
    const string& what,
    const List<point>& points,
    const string& consequence
) const
{
    const boolList inside = insideMesh(points);
    OStringStream outside;
    label first = -1;
    forAll(inside, i)
    {
        if (!inside[i])
        {
            outside << (first < 0 ? "" : " ") << i;
            first = first < 0 ? i : first;
        }
    }
    if (first >= 0)
    {
        WarningInFunction
            << type() << " " << name() << ": " << what.c_str() << " "
            << outside.str().c_str() << " of its " << points.size()
            << " lie outside the mesh (the first at " << points[first]
            << "): " << consequence.c_str() << "." << endl;
    }
}


void Foam::dropletFiber::fiberPopulation::warnPlacedOutside
(
    const std::vector<namedFiber>& fixed
) const
{
    // Nothing of these is wrong enough to stop (a mesh may grow, a fiber
    // may reach in), but each runs on without a word otherwise
    for (const auto& named : fixed)
    {
        const Eigen::Matrix3Xd& x = named.fiber.positions();
        List<point> points(label(x.cols()));
        forAll(points, i)
        {
            points[i] = toPoint(x.col(i));
        }
        warnPointsOutside
        (
            "fixed fiber '" + named.name + "': points", points,
            "there the fiber sees still air and no droplets, and a fiber "
            "with no point in the mesh bounds is removed at the first step"
        );
    }
    List<point> positions(label(injectors_.size()));
    forAll(positions, k)
    {
        positions[k] = toPoint(injectors_[k].spec().position);
    }
    const boolList inside = insideMesh(positions);
    forAll(inside, k)
    {
        if (!inside[k])
        {
            WarningInFunction
                << type() << " " << name() << ": injector '"
                << injectors_[k].spec().name.c_str() << "': position "
                << positions[k] << " lies outside the mesh: its fibers start"
                << " outside (in still air, with no droplets), and are "
                << "removed at once unless a point lies in the mesh bounds."
                << endl;
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dropletFiber::fiberPopulation::read
(
    const dictionary& fibersDict,
    const bool running
)
{
    checkFiberSourceKeys(fibersDict);
    holders_ =
        fiberOwnership::holderRuleFromName
        (
            getChoice
            (
                fibersDict, "holders", "cells",
                fiberOwnership::holderRuleNames()
            )
        );
    if (running)
    {
        // sources_ is the dictionary in force: any earlier edit of these
        // entries would have stopped the run
        checkFiberSourcesUnchanged(sources_, fibersDict);
        return;
    }
    sources_ = fibersDict;
    for (const auto& spec : readFiberInjectors(sources_))
    {
        injectors_.emplace_back(spec);
    }
    boxes_.reset(new processorBoxes(mesh_));
}


std::vector<::dropletFiber::FiberInjectorSpec>
Foam::dropletFiber::fiberPopulation::injectorSpecs() const
{
    std::vector<::dropletFiber::FiberInjectorSpec> specs;
    for (const auto& injector : injectors_)
    {
        specs.push_back(injector.spec());
    }
    return specs;
}


void Foam::dropletFiber::fiberPopulation::start
(
    const bool restored,
    const label stateProcessors,
    parallelStatistics& statistics
)
{
    // From the restart state of the start time, else from the dictionary
    std::vector<namedFiber> fixed;
    if (!restored)
    {
        fixed = readFixedFibers(sources_);
    }
    warnPlacedOutside(fixed);
    if (!restored)
    {
        heldFibers born;
        for (auto& named : fixed)
        {
            born.append(std::move(named.fiber), named.name, nextFiberId_++);
        }
        takeBornFibers(born, statistics);
        noteWeights();
        return;
    }
    nextFiberId_ = nextFiberIdAfterRestart();
    noteWeights();
    if (stateProcessors == 0)
    {
        // A serial run's state (decomposePar copies it to every processor):
        // each processor keeps the fibers it holds by the birth rule
        fiberOwnership::keepBornHere(*boxes_, held_, statistics, holders_);
    }
    else
    {
        // This processor's own fibers: passed on where the decomposition
        // changed since
        fiberOwnership::passOn(*boxes_, held_, statistics, holders_);
    }
    Info<< type() << " " << name() << ": " << count()
        << " fibers restored" << nl;
}


void Foam::dropletFiber::fiberPopulation::noteWeights()
{
    // The injectors are the same everywhere; the fibers held are not
    bool weighted = false;
    for (const auto& fiber : held_.fibers)
    {
        weighted = weighted || fiber.represents() != 1;
    }
    reduce(weighted, orOp<bool>());
    for (const auto& injector : injectors_)
    {
        weighted = weighted || injector.spec().represents != 1;
    }
    held_.weighted = weighted;
    if (weighted)
    {
        reportWeights();
    }
}


void Foam::dropletFiber::fiberPopulation::reportWeights() const
{
    Info<< type() << " " << name() << ": weighted fibers: each computed fiber"
        << " stands for the physical fibers it represents (the spray loses"
        << " that many times its capture; docs/model.md sec. 9)" << nl;
    for (const auto& injector : injectors_)
    {
        const ::dropletFiber::FiberInjectorSpec& s = injector.spec();
        Info<< "    injector " << s.name.c_str() << ": " << s.rate
            << " computed fibers/s, each represents " << s.represents
            << ": " << s.rate*s.represents << " physical fibers/s, glass "
            << s.massFlow() << " kg/s (" << 3600*s.massFlow() << " kg/h)"
            << nl;
    }
    Info<< "    fibers held now: " << count() << " computed, representing "
        << represented() << nl << endl;
}


void Foam::dropletFiber::fiberPopulation::inject
(
    parallelStatistics& statistics
)
{
    const scalar t = continuousTime();
    coreCall("injecting fibers", [&]() { injectFibers(t, statistics); });
}


void Foam::dropletFiber::fiberPopulation::removeLostAndPassOn
(
    parallelStatistics& statistics
)
{
    removeLostFibers();
    if (mesh_.moving())
    {
        boxes_->update();
    }
    fiberOwnership::passOn(*boxes_, held_, statistics, holders_);
}


std::pair<Foam::vector, Foam::vector>
Foam::dropletFiber::fiberPopulation::boundingBox() const
{
    vector lo(vector::uniform(GREAT));
    vector hi(vector::uniform(-GREAT));
    for (const ::dropletFiber::Fiber& fiber : held_.fibers)
    {
        const Eigen::Matrix3Xd& x = fiber.positions();
        for (Eigen::Index j = 0; j < x.cols(); ++j)
        {
            for (direction d = 0; d < 3; ++d)
            {
                lo[d] = min(lo[d], x(d, j));
                hi[d] = max(hi[d], x(d, j));
            }
        }
    }
    reduce(lo, minOp<vector>());
    reduce(hi, maxOp<vector>());
    return {lo, hi};
}


Foam::label Foam::dropletFiber::fiberPopulation::count() const
{
    return returnReduce(label(held_.size()), sumOp<label>());
}


Foam::scalar Foam::dropletFiber::fiberPopulation::mass() const
{
    scalar m = 0;
    for (const auto& fiber : held_.fibers)
    {
        m += fiber.represents()*fiber.totalMass();
    }
    return returnReduce(m, sumOp<scalar>());
}


Foam::scalar Foam::dropletFiber::fiberPopulation::represented() const
{
    scalar n = 0;
    for (const auto& fiber : held_.fibers)
    {
        n += fiber.represents();
    }
    return returnReduce(n, sumOp<scalar>());
}


Foam::scalar Foam::dropletFiber::fiberPopulation::pointsHere() const
{
    scalar fiberPoints = 0;
    for (const auto& fiber : held_.fibers)
    {
        fiberPoints += fiber.pointCount();
    }
    return fiberPoints;
}


::dropletFiber::BinderSums
Foam::dropletFiber::fiberPopulation::binderSums() const
{
    ::dropletFiber::BinderSums sums;
    for (const ::dropletFiber::Fiber& fiber : held_.fibers)
    {
        sums.add(fiber);
    }
    List<scalar> values(label(sums.values.size()), Zero);
    forAll(values, i)
    {
        values[i] = sums.values[std::size_t(i)];
    }
    Pstream::listCombineGather(values, plusEqOp<scalar>());
    forAll(values, i)
    {
        sums.values[std::size_t(i)] = values[i];
    }
    return sums;
}


Foam::List<Foam::scalar>
Foam::dropletFiber::fiberPopulation::dispersionSums() const
{
    List<scalar> sums(11, Zero);
    for (const ::dropletFiber::Fiber& fiber : held_.fibers)
    {
        if (fiber.immobile())
        {
            continue;
        }
        // Over the physical fibers: each computed one counts N times
        const scalar n = fiber.represents();
        const Eigen::Vector3d c = fiber.centreOfMass();
        sums[0] += n;
        for (int d = 0; d < 3; ++d)
        {
            sums[1 + d] += n*c(d);
            sums[4 + d] += n*(c(d)*c(d));
        }
        const Eigen::Matrix3Xd& u = fiber.state().turbulentVelocity;
        sums[7] += n*scalar(fiber.pointCount());
        for (int d = 0; d < 3 && u.cols(); ++d)
        {
            sums[8 + d] += n*u.row(d).squaredNorm();
        }
    }
    Pstream::listCombineGather(sums, plusEqOp<scalar>());
    return sums;
}


//- The entries of fibers the population reads (an injector's and a fixed fiber's own: fiberSettings.C)
static const Foam::wordList fiberSourceKeys
{
    "injectors", "fixed", "holders"
};


Foam::wordList Foam::dropletFiber::fiberPopulation::fibersEntries()
{
    return fiberSourceKeys;
}


// ************************************************************************* //
