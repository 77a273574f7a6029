/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    Settings and the coupling step. Read execute() from top to bottom to
    follow one parcel's mass: gathered, deposited on the grid (in parallel:
    on this processor's block, and by the processors whose blocks its
    kernel reaches on theirs),
    averaged, turned into collision mass on fiber segments, and captured by
    the fibers.

\*---------------------------------------------------------------------------*/

#include "dropletFiberCollision.H"
#include "dictionaryChecks.H"
#include "grid/NodeValueArray.hpp"
#include "dictionaryKeys.H"
#include "collisionSettings.H"
#include "plausibility.H"
#include "fiberStateIO.H"
#include "fiberOwnership.H"
#include "cloud.H"
#include "Time.H"
#include "fvMesh.H"
#include "PstreamReduceOps.H"
#include "clockValue.H"
#include "OStringStream.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(dropletFiberCollision, 0);
    addToRunTimeSelectionTable
    (
        functionObject,
        dropletFiberCollision,
        dictionary
    );
}
}


// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- The entries of the function object's dictionary: its own, read by
//  readOutputAndClouds() and read(), and those OpenFOAM v1912 reads from
//  every function object's dictionary
const Foam::wordList functionObjectKeys
{
    "clouds", "gather", "grid", "collision", "air", "fibers",
    "writeVtk", "writeGridVtk", "writeWindowValues", "windowState", "restart",
    // functionObject, functionObjectList: the object itself
    "type", "libs", "functionObjectLibs", "enabled", "log",
    // regionFunctionObject (fvMeshFunctionObject)
    "region", "subRegion",
    // timeControl: when execute() and write() are called
    "executeControl", "executeInterval", "writeControl", "writeInterval",
    "outputControl", "outputInterval",
    "timeStart", "timeEnd", "triggerStart", "triggerEnd", "controlMode",
    "deltaTCoeff", "nStepsToStartTimeChange",
    // writeFile: the per-step table
    "writePrecision", "writeToFile", "useUserTime",
    // set by postProcess -func 'name(field, ...)'
    "field", "fields"
};


//- dict with the per-step table's writePrecision: the entry, else 10 (more
//  digits than OpenFOAM's default: the table is compared across runs).
//  writeFile opens the table in its constructor with the precision in force
//  then, so the constructor must be given this too.
Foam::dictionary tableFileDict(const Foam::dictionary& dict)
{
    Foam::dictionary fileDict(dict);
    if (!fileDict.found("writePrecision"))
    {
        fileDict.add("writePrecision", 10);
    }
    return fileDict;
}


Foam::point toPoint(const Eigen::Vector3d& x)
{
    return Foam::point(x.x(), x.y(), x.z());
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::dropletFiberCollision::readOutputAndClouds
(
    const dictionary& dict
)
{
    writeFile::read(tableFileDict(dict));
    writeVtk_ = dropletFiber::getSwitch(dict, "writeVtk", true);
    writeGridVtk_ = dropletFiber::getSwitch(dict, "writeGridVtk", true);
    writeWindowValues_ =
        dropletFiber::getSwitch(dict, "writeWindowValues", false);
    {
        const word format = dropletFiber::getChoice
        (
            dict, "windowState", "smaller", {"smaller", "parcels", "nodeValues"}
        );
        using Format = ::dropletFiber::DensityGrid::WindowStateFormat;
        windowStateFormat_ =
            format == "parcels" ? Format::DepositLog
          : format == "nodeValues" ? Format::NodeValues
          : Format::Smaller;
    }

    cloudNames_ = dict.lookupOrDefault<wordList>("clouds", wordList());
    // A cloud named twice would be gathered twice: its parcels, their mass
    // and the mass captured from them counted double
    forAll(cloudNames_, i)
    {
        for (label j = 0; j < i; ++j)
        {
            if (cloudNames_[j] == cloudNames_[i])
            {
                FatalIOErrorInFunction(dict)
                    << "Entry 'clouds' names cloud '" << cloudNames_[i]
                    << "' twice: allowed are the names of the run's clouds,"
                    << " each at most once (or no entry: all clouds)."
                    << exit(FatalIOError);
            }
        }
    }
    // direct: the kinematic parcel types read parcel by parcel, others through
    // cloud::writeObjects; writeObjects: every cloud that way (the same values)
    gatherWriteObjects_ =
        dropletFiber::getChoice
        (
            dict, "gather", "direct", {"direct", "writeObjects"}
        ) == "writeObjects";
}


void Foam::functionObjects::dropletFiberCollision::buildStatefulParts
(
    const dictionary& dict
)
{
    // The injectors first: the memory check counts the fibers they give
    const dictionary fibersDict = dict.subOrEmptyDict("fibers");
    for (const auto& spec : dropletFiber::readFiberInjectors(fibersDict))
    {
        injectors_.emplace_back(spec);
    }
    const dictionary& gridDict = dict.subOrEmptyDict("grid");
    blocks_.reset
    (
        dropletFiber::checkedCoreCall
        (
            gridDict,
            [this]()
            {
                return new dropletFiber::gridBlocks(mesh_, gridSettings_.spec);
            }
        )
    );
    // The blocks first: the memory check counts the largest block's nodes
    checkMemory(dict);
    grid_.reset
    (
        dropletFiber::checkedCoreCall
        (
            dict,
            [this]()
            {
                return new ::dropletFiber::DensityGrid
                (
                    gridSettings_.spec,
                    gridSettings_.kernel,
                    int(gridSettings_.averagingSteps),
                    blocks_->block()
                );
            }
        )
    );
    depositReport_.reset
    (
        new dropletFiber::depositReport
        (
            type() + " " + name(), gridSettings_.spec, gridSettings_.kernel
        )
    );
}


void Foam::functionObjects::dropletFiberCollision::checkMemory
(
    const dictionary& dict
)
{
    std::vector<::dropletFiber::FiberInjectorSpec> specs;
    for (const auto& injector : injectors_)
    {
        specs.push_back(injector.spec());
    }
    const scalar deltaT = time_.deltaTValue();
    memory_ = dropletFiber::estimateMemory
    (
        gridSettings_, scalar(blocks_->largestBlockNodes()), specs, deltaT
    );
    dropletFiber::checkMemory(dict, memory_, specs, deltaT);
}


void Foam::functionObjects::dropletFiberCollision::checkStatefulPartsUnchanged
(
    const dictionary& dict,
    const dropletFiber::gridSettings& grid
) const
{
    dropletFiber::checkGridUnchanged
    (
        gridSettings_, grid, dict.subOrEmptyDict("grid")
    );
    // dict_ is the dictionary in force: any earlier edit of these entries
    // would have stopped the run
    dropletFiber::checkFiberSourcesUnchanged
    (
        dict_.subOrEmptyDict("fibers"), dict.subOrEmptyDict("fibers")
    );
}


void Foam::functionObjects::dropletFiberCollision::reportSettings() const
{
    const auto& g = gridSettings_.spec;
    const auto& kernel = gridSettings_.kernel;
    Info<< type() << " " << name() << ":" << nl << "    clouds: ";
    if (cloudNames_.empty())
    {
        Info<< "all";
    }
    else
    {
        Info<< cloudNames_;
    }
    Info<< (
               gatherWriteObjects_
             ? " (gather writeObjects: every cloud through cloud::writeObjects)"
             : " (gather direct: the stock solvers' parcel types read directly,"
               " parcel by parcel: kinematic, colliding, MPPIC, thermo, reacting,"
               " spray clouds; others through cloud::writeObjects; each cloud's"
               " route is logged when first read)"
           ) << nl;
    Info<< "    grid: (" << g.lower.x() << ' ' << g.lower.y() << ' ' << g.lower.z()
        << ") to (" << g.upper.x() << ' ' << g.upper.y() << ' ' << g.upper.z()
        << "), nodes (" << g.nodes[0] << ' ' << g.nodes[1] << ' ' << g.nodes[2]
        << "), averagingSteps " << gridSettings_.averagingSteps
        << ", beta " << kernel.beta
        << ", rMaxCap " << kernel.rMaxCap
        << ", cloudInCellBelow " << kernel.cloudInCellBelow
        << ", negligibleWeight " << kernel.negligibleWeight
        << ", vectorised " << Switch(kernel.vectorised).c_str()
        << (
               grid_->batchedKernel()
             ? " (node weights: batched AVX2 + FMA)"
             : kernel.vectorised
             ? " (node weights: per node, this CPU has no AVX2 + FMA)"
             : " (node weights: per node)"
           ) << nl
        << "    collision: samples per segment " << collision_.samples
        << " (1: midpoint, 0: one per grid spacing), radiusAverage "
        << dropletFiber::radiusAverageName(collision_.radiusAverage)
        << ", mode " << dropletFiber::collisionModeReport(collision_).c_str()
        << ", depletion " << Switch(depletion_).c_str()
        << (
               depletion_
             ? " (the captured droplets leave their parcels)"
             : " (the spray keeps every droplet: the paper's behaviour)"
           ) << nl;
    // Each rank asks its own CPU: on a cluster of mixed CPUs the ranks would
    // weight nodes with the two kernels, which agree to ~1e-14, not to the bit
    const bool batchedHere = grid_->batchedKernel();
    if
    (
        returnReduce(batchedHere, orOp<bool>())
     != returnReduce(batchedHere, andOp<bool>())
    )
    {
        WarningInFunction
            << "grid.vectorised: some ranks weight nodes with the batched"
            << " AVX2 + FMA kernel, others (CPUs without it) node by node;"
            << " the results agree to ~1e-14, not to the bit. Set"
            << " 'vectorised false;' for bitwise reproducible runs." << endl;
    }
    blocks_->report(Info);
    air_->report(Info);
    // The fibers this processor holds
    scalar fiberPoints = 0;
    for (const auto& fiber : held_.fibers)
    {
        fiberPoints += fiber.pointCount();
    }
    dropletFiber::reportMemory(Info, memory_, fiberPoints);
    const auto& s = solverSettings_;
    Info<< "    fibers: gravity (" << s.gravity.x() << ' ' << s.gravity.y() << ' '
        << s.gravity.z() << "), drag "
        << ::dropletFiber::dragModelName(s.drag.model).c_str()
        << ", theta " << s.theta << ", injectors " << label(injectors_.size())
        << ", fibers now " << fiberCount() << nl;
    reportTurbulence();
    Info<< "    output: writeVtk " << Switch(writeVtk_).c_str()
        << ", writeGridVtk " << Switch(writeGridVtk_).c_str() << nl << endl;
}


Foam::boolList Foam::functionObjects::dropletFiberCollision::insideMesh
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


void Foam::functionObjects::dropletFiberCollision::warnPlacedOutside
(
    const std::vector<dropletFiber::namedFiber>& fixed
) const
{
    // Nothing of these is wrong enough to stop (a mesh may grow, a fiber
    // may reach in), but each runs on without a word otherwise
    const boundBox& meshBox = mesh_.bounds();
    const auto& g = gridSettings_.spec;
    const boundBox gridBox(toPoint(g.lower), toPoint(g.upper));
    if (!gridBox.overlaps(meshBox))
    {
        WarningInFunction
            << type() << " " << name() << ": the grid box, lower "
            << gridBox.min() << " upper " << gridBox.max() << ", lies "
            << "entirely outside the mesh bounds " << meshBox.min() << " "
            << meshBox.max() << ": no droplet reaches it, so the fibers "
            << "capture nothing." << nl
            << "    Set grid lower/upper inside the mesh." << endl;
    }
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


void Foam::functionObjects::dropletFiberCollision::warnPointsOutside
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


Foam::wordList
Foam::functionObjects::dropletFiberCollision::selectClouds() const
{
    if (cloudNames_.empty())
    {
        return dropletFiber::cloudParcels::cloudNames(mesh_);
    }

    // One look-up per named cloud (the sorted list of all clouds only for
    // the error message: building it every step was measurable)
    for (const word& cloudName : cloudNames_)
    {
        if (!mesh_.foundObject<cloud>(cloudName))
        {
            const wordList available =
                dropletFiber::cloudParcels::cloudNames(mesh_);
            const word startTimeName =
                time_.timeName(time_.startTime().value());
            FatalIOErrorInFunction(dict_)
                << "Cloud '" << cloudName << "' named in entry 'clouds' of "
                << type() << " '" << name() << "' does not exist at time "
                << time_.timeName() << "." << nl
                << "    Clouds that exist: " << available << nl
                << "    (A cloud created by another function object exists "
                << "from the first time step on, wherever it is listed.)"
                << nl << "    Check:" << nl
                << "    - the cloud's name in 'clouds';" << nl
                << "    - a warning or error of the cloud's own loading above in"
                << " the log (a cloud function object that fails to load is"
                << " only warned about, and the run goes on without it);" << nl
                << "    - its files in " << startTimeName << "/" << cloud::prefix
                << "/" << cloudName
                << (Pstream::parRun() ? " of every processor" : "")
                << ": reconstructPar does not carry over a colliding cloud's"
                << " collision records (collisionRecords*), so a cloud"
                << " reconstructed that way may fail to load; restart from the"
                << " decomposed case, or from a time the cloud wrote itself."
                << exit(FatalIOError);
        }
    }
    return cloudNames_;
}


void Foam::functionObjects::dropletFiberCollision::gatherParcels()
{
    parcels_.clear();
    stepClouds_.clear();
    cloudStarts_.clear();
    for (const word& cloudName : selectClouds())
    {
        stepClouds_.append(cloudName);
        cloudStarts_.append(parcels_.size());
        const cloud& c = mesh_.lookupObject<cloud>(cloudName);
        logCloudRoute(c);
        parcels_.append(c, dict_, gatherWriteObjects_);
    }
}


void Foam::functionObjects::dropletFiberCollision::warnImplausibleDroplets()
{
    // At the first step with parcels (on any processor), once
    if (checkedDroplets_)
    {
        return;
    }
    scalar lo = VGREAT;
    scalar hi = -VGREAT;
    for (const scalar rho : parcels_.rho)
    {
        lo = min(lo, rho);
        hi = max(hi, rho);
    }
    reduce(lo, minOp<scalar>());
    reduce(hi, maxOp<scalar>());
    if (lo > hi)
    {
        return;
    }
    checkedDroplets_ = true;
    const auto& range = dropletFiber::dropletDensityRange;
    const string text =
        dropletFiber::implausible(lo < range.lo ? lo : hi, range);
    if (!text.empty())
    {
        WarningInFunction
            << type() << " " << name() << ": the droplet density (the"
            << " parcels' rho: the clouds' constantProperties rho0 or their"
            << " injection data) "
            << text.c_str() << endl;
    }
}


void Foam::functionObjects::dropletFiberCollision::logCloudRoute
(
    const cloud& c
)
{
    if (!loggedClouds_.insert(c.name()))
    {
        return;
    }
    const bool direct =
        !gatherWriteObjects_ && dropletFiber::cloudParcels::readsDirectly(c);
    Info<< type() << " " << name() << ": cloud '" << c.name() << "' (type "
        << c.type() << ") read "
        << (
               direct
             ? "parcel by parcel (a stock solver's parcel type)"
             : gatherWriteObjects_
             ? "through cloud::writeObjects (entry gather writeObjects)"
             : "through cloud::writeObjects (gather direct reads the stock"
               " solvers' parcel types only)"
           );
    if (depletion_ && !dropletFiber::cloudParcels::readsDirectly(c))
    {
        Info<< "; the droplets the fibers capture cannot be removed from"
            << " its parcels";
    }
    Info<< nl;
}


::dropletFiber::StepStatistics
Foam::functionObjects::dropletFiberCollision::depositParcels(const scalar dt)
{
    if (depletion_)
    {
        grid_->keepTablesNear(fiberNodes());
    }
    using stage = dropletFiber::parallelStatistics::stage;
    parallelStatistics_.timed
    (
        stage::deposit, [&]() { depositLocalParcels(dt); }
    );
    blocks_->depositCopies
    (
        *grid_, stepParcels_, dt, parallelStatistics_,
        [&](const std::size_t i) { depositOwnParcel(i, dt); },
        // Discrete hits draw whole droplets from the node sums: a last-bit
        // difference can change a count, so there the sums are made the
        // same on every decomposition (docs/model.md sec. 4, grid blocks)
        collision_.mode == ::dropletFiber::CollisionMode::Discrete
    );
    const ::dropletFiber::StepStatistics local = grid_->stepStatistics();
    const ::dropletFiber::StepStatistics& copies = grid_->copyStatistics();
    parallelStatistics_.countDeposit
    (
        scalar(local.parcels),
        scalar(copies.parcels),
        scalar(local.nodesVisited + copies.nodesVisited)
    );
    parallelStatistics_.timed(stage::deposit, [&]() { grid_->commitStep(); });
    const ::dropletFiber::StepStatistics stats = summedOverProcessors(local);
    countCappedParcels(label(stats.parcelsCapped));
    return stats;
}


void Foam::functionObjects::dropletFiberCollision::depositLocalParcels
(
    const scalar dt
)
{
    // Deposited by blocks_->depositCopies, with the copies, in key order
    stepParcels_.clear();
    for (label i = 0; i < parcels_.size(); ++i)
    {
        ::dropletFiber::Parcel& p = stepParcels_.emplace_back();
        p.position = dropletFiber::toEigen(parcels_.position[i]);
        p.velocity = dropletFiber::toEigen(parcels_.U[i]);
        p.diameter = parcels_.d[i];
        p.nParticle = parcels_.nParticle[i];
        p.rhoDroplet = parcels_.rho[i];
    }
}


void Foam::functionObjects::dropletFiberCollision::depositOwnParcel
(
    const std::size_t i,
    const scalar dt
)
{
    try
    {
        grid_->deposit(stepParcels_[i], dt);
    }
    catch (const std::exception& e)
    {
        // A parcel with NaN or negative values: a broken cloud, not ours
        FatalErrorInFunction
            << type() << " " << name() << ": parcel " << label(i)
            << " at " << parcels_.position[label(i)] << " cannot be deposited: "
            << e.what() << exit(FatalError);
    }
}


::dropletFiber::StepStatistics
Foam::functionObjects::dropletFiberCollision::summedOverProcessors
(
    ::dropletFiber::StepStatistics stats
)
{
    // One reduction for the four sums the function object uses (the count
    // is exact in a double)
    List<scalar> sums(4);
    sums[0] = stats.massIn;
    sums[1] = stats.massDeposited;
    sums[2] = stats.massOutside;
    sums[3] = scalar(stats.parcelsCapped);
    Pstream::listCombineGather(sums, plusEqOp<scalar>());
    Pstream::listCombineScatter(sums);
    stats.massIn = sums[0];
    stats.massDeposited = sums[1];
    stats.massOutside = sums[2];
    stats.parcelsCapped = label(sums[3]);
    return stats;
}


void Foam::functionObjects::dropletFiberCollision::countCappedParcels
(
    const label capped
)
{
    if (capped > 0 && totals_.parcelsCapped == 0)
    {
        WarningInFunction
            << type() << " " << name() << ": the influence radius of "
            << capped << " parcels was capped at rMaxCap = "
            << gridSettings_.kernel.rMaxCap
            << " m at time " << time_.timeName() << nl
            << "    (warned once; the count is reported at write times)" << endl;
    }
    totals_.parcelsCapped += capped;
}


void Foam::functionObjects::dropletFiberCollision::injectFibers(const scalar t)
{
    // Every processor advances every injector alike (cheap) and keeps the
    // fibers born in its cells
    dropletFiber::heldFibers born;
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
    takeBornFibers(born);
}


void Foam::functionObjects::dropletFiberCollision::takeBornFibers
(
    dropletFiber::heldFibers& born
)
{
    // All processors have all of them: the mass is added alike everywhere,
    // in the order of birth (a serial run's)
    for (const auto& fiber : born.fibers)
    {
        totals_.fiberMassAdded += fiber.totalMass();
    }
    dropletFiber::fiberOwnership::keepBornHere
    (
        *boxes_, born, parallelStatistics_, fiberHolders_
    );
    for (std::size_t k = 0; k < born.size(); ++k)
    {
        held_.append(std::move(born.fibers[k]), born.origin[k], born.id[k]);
    }
}


std::vector<Eigen::Vector3d>
Foam::functionObjects::dropletFiberCollision::collisionSamplePoints
(
    std::vector<int>& samplesPerSegment
) const
{
    const auto& spec = grid_->spec();
    std::vector<Eigen::Vector3d> points;
    samplesPerSegment.clear();
    for (const ::dropletFiber::Fiber& fiber : held_.fibers)
    {
        const Eigen::Matrix3Xd& x = fiber.positions();
        for (Eigen::Index j = 0; j < fiber.segmentCount(); ++j)
        {
            const int samples =
                ::dropletFiber::collisionSamples
                (
                    spec, x.col(j), x.col(j + 1), collision_
                );
            samplesPerSegment.push_back(samples);
            for (int s = 0; s < samples; ++s)
            {
                points.push_back
                (
                    ::dropletFiber::samplePoint(x.col(j), x.col(j + 1), samples, s)
                );
            }
        }
    }
    return points;
}


Foam::label Foam::functionObjects::dropletFiberCollision::collisionMasses
(
    const scalar dt,
    const std::vector<::dropletFiber::DropletFieldValue>& fields,
    const std::vector<int>& samplesPerSegment,
    double* sampleMasses,
    ::dropletFiber::CaptureSources& capture
) const
{
    const std::vector<::dropletFiber::Fiber>& fibers = held_.fibers;
    capture.clear();
    capture.resize(fibers.size());
    label samplesOutside = 0;
    std::size_t next = 0;
    std::size_t segment = 0;
    for (std::size_t f = 0; f < fibers.size(); ++f)
    {
        const ::dropletFiber::Fiber& fiber = fibers[f];
        const Eigen::Matrix3Xd& x = fiber.positions();
        const Eigen::Matrix3Xd& v = fiber.velocities();
        capture[f].resize(fiber.segmentCount());
        for (Eigen::Index j = 0; j < fiber.segmentCount(); ++j)
        {
            const Eigen::Vector3d segmentVelocity = 0.5*(v.col(j) + v.col(j + 1));
            const int samples = samplesPerSegment[segment++];
            const ::dropletFiber::SegmentCollision c =
                ::dropletFiber::collisionMassFromSamples
                (
                    fields.data() + next,
                    samples,
                    x.col(j),
                    x.col(j + 1),
                    fiber.material().radius,
                    segmentVelocity,
                    dt,
                    collision_,
                    sampleMasses ? sampleMasses + next : nullptr
                );
            next += std::size_t(samples);
            capture[f][j].mass = c.mass;
            capture[f][j].momentum = c.momentum;
            samplesOutside += c.samplesOutside;
        }
    }
    return samplesOutside;
}


::dropletFiber::CaptureSources
Foam::functionObjects::dropletFiberCollision::collide(const scalar dt)
{
    // The sample points of the segments of the fibers held here, then their
    // field values from the grid's blocks (one exchange), then the masses:
    // the arithmetic of collisionMass
    using stage = dropletFiber::parallelStatistics::stage;
    std::vector<int> samplesPerSegment;
    std::vector<Eigen::Vector3d> points;
    parallelStatistics_.timed
    (
        stage::collision,
        [&]() { points = collisionSamplePoints(samplesPerSegment); }
    );
    parallelStatistics_.countCollisionSamples(points.size());
    // Depletion: each sample's interpolated mass sum too; every sample's
    // mass (the hits are counted per sample)
    std::vector<double> massSums;
    std::vector<double> sampleMasses(points.size());
    const std::vector<::dropletFiber::DropletFieldValue> fields =
        blocks_->sample
        (
            *grid_, points, parallelStatistics_,
            depletion_ ? &massSums : nullptr
        );

    ::dropletFiber::CaptureSources capture;
    label samplesOutside = 0;
    parallelStatistics_.timed
    (
        stage::collision,
        [&]()
        {
            samplesOutside = collisionMasses
            (
                dt, fields, samplesPerSegment,
                sampleMasses.data(), capture
            );
        }
    );
    warnSamplesOutside(samplesOutside);
    if (depletion_)
    {
        const std::vector<double> granted =
            limitCapture
            (
                fields, points, massSums, sampleMasses, samplesPerSegment, dt,
                capture
            );
        countHits(fields, granted, samplesPerSegment, capture);
    }
    else
    {
        countHits(fields, sampleMasses, samplesPerSegment, capture);
    }
    return capture;
}


void Foam::functionObjects::dropletFiberCollision::warnSamplesOutside
(
    const label samplesOutside
)
{
    // Once warned, no more reductions (the flag is the same on every
    // processor: it follows a reduced count)
    if (warnedSamplesOutside_)
    {
        return;
    }
    const label total = returnReduce(samplesOutside, sumOp<label>());
    if (total > 0)
    {
        const auto& g = gridSettings_.spec;
        WarningInFunction
            << type() << " " << name() << ": " << total
            << " collision sample points of fiber segments lie outside the"
            << " grid box at time " << time_.timeName()
            << ": those segments see no droplets there." << nl
            << "    Enlarge grid lower (" << g.lower.x() << ' ' << g.lower.y()
            << ' ' << g.lower.z() << ") / upper (" << g.upper.x() << ' '
            << g.upper.y() << ' ' << g.upper.z() << ") to cover the fibers"
            << " (warned once)." << endl;
        warnedSamplesOutside_ = true;
    }
}


void Foam::functionObjects::dropletFiberCollision::removeLostFibers()
{
    // The running totals go on from the master's; the others' removals are
    // added to it (a serial run adds them one after another, as always)
    const boundBox& box = mesh_.bounds();
    scalar massRemoved = Pstream::master() ? totals_.fiberMassRemoved : 0;
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
            massRemoved += fiber.totalMass();
            ++removed;
            return false;
        }
    );
    totals_.fiberMassRemoved = returnReduce(massRemoved, sumOp<scalar>());
    totals_.fibersRemoved += returnReduce(removed, sumOp<label>());
}


void Foam::functionObjects::dropletFiberCollision::takeStartFibers
(
    std::vector<dropletFiber::namedFiber>& fixed,
    const bool restored,
    const dictionary& dict
)
{
    if (!restored)
    {
        dropletFiber::heldFibers born;
        for (auto& named : fixed)
        {
            born.append(std::move(named.fiber), named.name, nextFiberId_++);
        }
        takeBornFibers(born);
        return;
    }
    nextFiberId_ = nextFiberIdAfterRestart(dict);
    if (stateProcessors_ == 0)
    {
        // A serial run's state (decomposePar copies it to every processor):
        // each processor keeps the fibers it holds by the birth rule
        dropletFiber::fiberOwnership::keepBornHere
        (
            *boxes_, held_, parallelStatistics_, fiberHolders_
        );
    }
    else
    {
        // This processor's own fibers: passed on where the decomposition
        // changed since
        dropletFiber::fiberOwnership::passOn
        (
            *boxes_, held_, parallelStatistics_, fiberHolders_
        );
    }
}


Foam::label Foam::functionObjects::dropletFiberCollision::fiberCount() const
{
    return returnReduce(label(held_.size()), sumOp<label>());
}


Foam::scalar Foam::functionObjects::dropletFiberCollision::fiberMass() const
{
    scalar m = 0;
    for (const auto& fiber : held_.fibers)
    {
        m += fiber.totalMass();
    }
    return returnReduce(m, sumOp<scalar>());
}


Foam::scalar Foam::functionObjects::dropletFiberCollision::capturedMass
(
    const ::dropletFiber::CaptureSources& capture
)
{
    scalar m = 0;
    for (const auto& fiberCapture : capture)
    {
        for (const auto& segment : fiberCapture)
        {
            m += segment.mass;
        }
    }
    return m;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::dropletFiberCollision::dropletFiberCollision
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, "dropletFiber", tableFileDict(dict)),
    dict_(dict),
    cloudNames_(),
    gatherWriteObjects_(false),
    lastTimeIndex_(-1),
    clock_(0),
    clockIndex_(-1),
    parcels_(),
    depletion_(true),
    depletionSteps_(0),
    limitedSteps_(0),
    removalRestored_(false),
    loggedLimit_(false),
    loggedHitsCut_(false),
    checkedDroplets_(false),
    warnedSamplesOutside_(false),
    nextFiberId_(0),
    stateProcessors_(0),
    restartFresh_(false),
    writeVtk_(true),
    writeGridVtk_(true),
    writeWindowValues_(false),
    windowStateFormat_(::dropletFiber::DensityGrid::WindowStateFormat::Smaller)
{
    read(dict);
    boxes_.reset(new dropletFiber::processorBoxes(mesh_));
    // The table's columns per liquid species; the state's totals of them
    if (depletion_)
    {
        findLiquidSpecies();
    }

    // Fibers: from the restart state of the start time, else from the
    // dictionary
    std::vector<dropletFiber::namedFiber> fixed;
    const bool restored = readStateOnEveryProcessor();
    if (!restored)
    {
        fixed = dropletFiber::readFixedFibers(dict.subOrEmptyDict("fibers"));
    }
    warnPlacedOutside(fixed);
    takeStartFibers(fixed, restored, dict);
    if (restored)
    {
        Info<< type() << " " << this->name() << ": " << fiberCount()
            << " fibers restored" << nl;
    }
    applyRemovalBeforeFirstStep();

    const fileName vtkDir = baseFileDir()/name/time_.timeName(time_.startTime().value());
    if (Pstream::master() && (writeVtk_ || writeGridVtk_))
    {
        mkDir(vtkDir);
    }
    fibersSeries_.reset(new ::dropletFiber::SeriesFile(vtkDir/"fibers.vtp.series"));
    gridSeries_.reset(new ::dropletFiber::SeriesFile(vtkDir/"grid.vti.series"));
    dropletFiber::checkedCoreCall
    (
        dict,
        [this]()
        {
            fibersSeries_->load(time_.value() + 0.5*time_.deltaTValue());
            gridSeries_->load(time_.value() + 0.5*time_.deltaTValue());
        }
    );
    stateMarker_.reset
    (
        new dropletFiber::restartStateMarker
        (
            time_, name, [this]() { return stateFollowsWrite(); }
        )
    );

    reportSettings();
    if (writeToFile())
    {
        writeFileHeader(file());
    }
}


Foam::functionObjects::dropletFiberCollision::~dropletFiberCollision() = default;


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::dropletFiberCollision::read(const dictionary& dict)
{
    // Called at construction, and again whenever the dictionary was edited
    // during the run (runTimeModifiable): what carries no state is applied,
    // an edit of what does stops the run (checkStatefulPartsUnchanged)
    const bool running = bool(grid_);
    dropletFiber::checkKeys(dict, functionObjectKeys);
    fvMeshFunctionObject::read(dict);
    readOutputAndClouds(dict);
    // Read at construction only: fresh ignores the restart state
    restartFresh_ =
        dropletFiber::getChoice
        (
            dict, "restart", "continue", {"continue", "fresh"}
        ) == "fresh";
    const dropletFiber::gridSettings grid =
        dropletFiber::readGridSettings(dict.subOrEmptyDict("grid"), mesh_);
    collision_ = dropletFiber::readCollisionSettings(dict);
    const bool depletion = dropletFiber::readDepletion(dict);
    if (running && depletion != depletion_)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'collision.depletion' was edited during the run ("
            << Switch(depletion_).c_str() << " -> "
            << Switch(depletion).c_str() << "): it is read at the start"
            << " only (the per-step table's columns follow it). Restart"
            << " the run to change it." << exit(FatalIOError);
    }
    depletion_ = depletion;
    air_.reset
    (
        new dropletFiber::airSampler(mesh_, dict.subOrEmptyDict("air"))
    );
    solverSettings_ =
        dropletFiber::readFiberSolverSettings(dict.subOrEmptyDict("fibers"), time_);
    solver_.reset(new ::dropletFiber::FiberSolver(solverSettings_));
    turbulence_ =
        dropletFiber::readFiberTurbulence(dict.subOrEmptyDict("fibers"), mesh_);
    fiberHolders_ =
        dropletFiber::fiberOwnership::holderRuleFromName
        (
            dropletFiber::getChoice
            (
                dict.subOrEmptyDict("fibers"), "holders", "cells",
                dropletFiber::fiberOwnership::holderRuleNames()
            )
        );

    if (running)
    {
        checkStatefulPartsUnchanged(dict, grid);
        dict_ = dict;
        Info<< type() << " " << name() << ": settings re-read at time "
            << time_.timeName() << nl;
        reportSettings();
    }
    else
    {
        gridSettings_ = grid;
        dict_ = dict;
        buildStatefulParts(dict);
        // Unit slips run, warned once at the start
        dropletFiber::warnImplausibleFibers(dict.subOrEmptyDict("fibers"));
        dropletFiber::warnImplausibleAir(dict.subOrEmptyDict("air"));
        dropletFiber::warnImplausibleSpacing
        (
            dict.subOrEmptyDict("grid"), gridSettings_, mesh_
        );
    }
    return true;
}


bool Foam::functionObjects::dropletFiberCollision::execute()
{
    // Once per time step, whatever the function object's execute control
    if (time_.timeIndex() == lastTimeIndex_)
    {
        return true;
    }
    lastTimeIndex_ = time_.timeIndex();
    const scalar dt = time_.deltaTValue();
    stepSummary step;
    parallelStatistics_.startStep();

    // 1.-2. The parcels of this step, onto the grid, averaged over the window
    clockValue depositionStart(true);
    gatherAndDeposit(dt, step);
    step.depositionTime = depositionStart.elapsed();
    depositReport_->record(step.deposit, step.depositionTime, time_.timeName());

    // 3. New fibers
    clockValue fiberStart(true);
    const scalar t = continuousTime();
    coreCall("injecting fibers", [&]() { injectFibers(t); });
    step.fiberTime = fiberStart.elapsed();

    // 4. Collision mass of every segment; with depletion taken from the parcels
    clockValue collisionStart(true);
    ::dropletFiber::CaptureSources capture = collideAndDeplete(dt);
    step.collisionTime = collisionStart.elapsed();

    // 5. Advance the fibers: capture, air drag, bending, inextensibility
    fiberStart.update();
    advanceAndCount(dt, capture, step);

    // 6. Fibers that left; the others to the processor now holding their
    //    first point
    passFibersOn();
    step.fiberTime += scalar(fiberStart.elapsed());
    rebalanceBlocks(dt);

    // 7. Report; at write times the restart state and the mass balances
    reportAndWriteState(step);
    return true;
}


void Foam::functionObjects::dropletFiberCollision::gatherAndDeposit
(
    const scalar dt,
    stepSummary& step
)
{
    // 1. The parcels of this step, on this processor (after a restart, with
    //    the removal of the step restarted from)
    if (removalRestored_)
    {
        coreCall
        (
            "removing the droplets captured before the restart",
            [this]() { applyRestoredRemoval(); }
        );
    }
    gatherParcels();
    warnImplausibleDroplets();
    step.parcels = returnReduce(parcels_.size(), sumOp<label>());
    step.droplets = returnReduce(parcels_.nDroplets(), sumOp<scalar>());

    // 2. Onto the grid; summed across processors; averaged over the window
    step.deposit =
        coreCall("depositing the parcels", [&]() { return depositParcels(dt); });
    totals_.parcelMass += step.deposit.massIn;
    totals_.deposited += step.deposit.massDeposited;
    totals_.outside += step.deposit.massOutside;
}


::dropletFiber::CaptureSources
Foam::functionObjects::dropletFiberCollision::collideAndDeplete(const scalar dt)
{
    // 4. Stochastic collision mass of every segment, from the grid (in
    //    parallel: of the fibers this processor holds)
    ::dropletFiber::CaptureSources capture =
        coreCall("colliding fibers and droplets", [&]() { return collide(dt); });

    // 4b. Depletion: the captured droplets leave their parcels
    if (depletion_)
    {
        coreCall
        (
            "removing the captured droplets from the parcels",
            [&]() { depleteParcels(dt); }
        );
    }
    return capture;
}


void Foam::functionObjects::dropletFiberCollision::advanceAndCount
(
    const scalar dt,
    ::dropletFiber::CaptureSources& capture,
    stepSummary& step
)
{
    const ::dropletFiber::StepReport report =
        coreCall
        (
            "advancing the fibers", [&]() { return advanceFibers(dt, capture); }
        );
    step.capturedStep = returnReduce(capturedMass(capture), sumOp<scalar>());
    step.maxSegmentLengthError = report.maxSegmentLengthError;
    step.subSteps = report.subSteps;
    totals_.captured += step.capturedStep;
    if (depletion_)
    {
        depletionStep_.captured = step.capturedStep;
        depletionRun_.demanded += depletionStep_.demanded;
        depletionRun_.captured += depletionStep_.captured;
        depletionRun_.removed += depletionStep_.removed;
        ++depletionSteps_;
        limitedSteps_ += depletionStep_.nodesLimited > 0 ? 1 : 0;
    }
}


void Foam::functionObjects::dropletFiberCollision::passFibersOn()
{
    removeLostFibers();
    if (mesh_.moving())
    {
        boxes_->update();
    }
    dropletFiber::fiberOwnership::passOn
    (
        *boxes_, held_, parallelStatistics_, fiberHolders_
    );
}


void Foam::functionObjects::dropletFiberCollision::reportAndWriteState
(
    const stepSummary& step
)
{
    reportStep(step);
    writeParallelStatistics();
    if (time_.writeTime())
    {
        coreCall("writing the restart state", [this]() { writeState(); });
        writeBinderDistribution();
        reportConservation();
        reportBinderBalance();
        parallelStatistics_.reportBalance
        (
            Info, type() + " " + name(), time_.timeName()
        );
        reportCloudBalance();
        depositReport_->reportAtWrite(time_.timeName());
    }
}


bool Foam::functionObjects::dropletFiberCollision::write()
{
    coreCall("writing the VTK files", [this]() { writeVtkFiles(); });
    return true;
}

// ************************************************************************* //
