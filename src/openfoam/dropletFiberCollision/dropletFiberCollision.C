/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    Settings and the coupling step. Read execute() from top to bottom to
    follow one parcel's mass: gathered, deposited on the grid, summed across
    processors, averaged, turned into collision mass on fiber segments, and
    captured by the fibers.

\*---------------------------------------------------------------------------*/

#include "dropletFiberCollision.H"
#include "dictionaryChecks.H"
#include "fiberStateIO.H"
#include "fiberDistribution.H"
#include "cloud.H"
#include "Time.H"
#include "fvMesh.H"
#include "PstreamReduceOps.H"
#include "clockValue.H"
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


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::dropletFiberCollision::readGrid
(
    const dictionary& dict
)
{
    using namespace dropletFiber;
    const dictionary gridDict = dict.subOrEmptyDict("grid");
    const boundBox meshBox = mesh_.bounds();

    const vector lower = gridDict.lookupOrDefault<vector>("lower", meshBox.min());
    const vector upper = gridDict.lookupOrDefault<vector>("upper", meshBox.max());
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (!(upper[d] > lower[d]))
        {
            FatalIOErrorInFunction(gridDict)
                << "Entries 'lower' " << lower << " and 'upper' " << upper
                << ": upper must be greater than lower in every direction "
                << "(a flat direction of a 2D grid still needs its thickness)."
                << exit(FatalIOError);
        }
    }

    // A 2D mesh's empty direction is flat (one node layer) unless given
    const Vector<label> geometricD = mesh_.geometricD();
    Vector<label> nodes(50, 50, 50);
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (geometricD[d] < 0)
        {
            nodes[d] = 1;
        }
    }
    if (gridDict.found("nodes") && gridDict.found("spacing"))
    {
        FatalIOErrorInFunction(gridDict)
            << "Entries 'nodes' and 'spacing' are both given: give one."
            << exit(FatalIOError);
    }
    if (gridDict.found("nodes"))
    {
        nodes = gridDict.get<Vector<label>>("nodes");
    }
    else if (gridDict.found("spacing"))
    {
        const scalar h = getPositive(gridDict, "spacing");
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (nodes[d] != 1)
            {
                nodes[d] = max(2, label(std::round((upper[d] - lower[d])/h)) + 1);
            }
        }
    }
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (nodes[d] < 1)
        {
            FatalIOErrorInFunction(gridDict)
                << "Entry 'nodes' is " << nodes
                << ": allowed are at least 1 node per direction (1: a flat "
                << "direction), and at least 2 directions with 2 or more."
                << exit(FatalIOError);
        }
    }

    gridSpec_.lower = dropletFiber::toEigen(lower);
    gridSpec_.upper = dropletFiber::toEigen(upper);
    gridSpec_.nodes = {{int(nodes.x()), int(nodes.y()), int(nodes.z())}};
    checkedCoreCall(gridDict, [this]() { gridSpec_.validate(); });

    averagingSteps_ = getLabelInRange(gridDict, "averagingSteps", 1, 1, 100000);
    const scalar defaultBeta = 0.025;   // the paper's value
    kernel_.beta =
        getCheckedScalar
        (
            gridDict, "beta", &defaultBeta,
            [](scalar b) { return b > 0 && b <= 1; },
            "in (0, 1] (eq. 18; the paper uses 0.025)"
        );
    kernel_.rMaxCap = getNonNegative(gridDict, "rMaxCap", 0);
    // Better than the paper (docs/validation.md): parcels whose kernel the grid
    // cannot resolve are deposited with cloud-in-cell weights; 0 = the paper
    kernel_.cloudInCellBelow = getNonNegative(gridDict, "cloudInCellBelow", 0.5);
    // Nodes whose weight would be below this fraction of the parcel's largest
    // are not evaluated (round-off level by default; 0 = exact tails)
    const scalar defaultNegligible = 1e-17;
    kernel_.negligibleWeight =
        getCheckedScalar
        (
            gridDict, "negligibleWeight", &defaultNegligible,
            [](scalar e) { return e >= 0 && e <= 1e-6; },
            "in [0, 1e-6] (0: every node within reach is evaluated)"
        );
    // Node weights with the batched AVX2 + FMA loop where the CPU has it; false:
    // node by node, the same results to the bit on every CPU (src/core/grid/KernelBuild.hpp)
    kernel_.vectorised = getSwitch(gridDict, "vectorised", true);
    const word dim =
        getChoice(gridDict, "dimension", "automatic", {"automatic", "2", "3"});
    kernel_.dimension =
        dim == "2" ? ::dropletFiber::KernelDimension::TwoD
      : dim == "3" ? ::dropletFiber::KernelDimension::ThreeD
      : ::dropletFiber::KernelDimension::Automatic;
    checkedCoreCall(gridDict, [this]() { kernel_.validate(); });

    const word radius =
        getChoice(gridDict, "radiusAverage", "mass", {"number", "mass"});
    collision_.radiusAverage =
        radius == "number"
      ? ::dropletFiber::RadiusAverage::Number
      : ::dropletFiber::RadiusAverage::Mass;
}


void Foam::functionObjects::dropletFiberCollision::readCollision
(
    const dictionary& dict
)
{
    using namespace dropletFiber;
    const dictionary collisionDict = dict.subOrEmptyDict("collision");
    const word sampling =
        getChoice(collisionDict, "sampling", "midpoint", {"midpoint", "integrated"});
    // midpoint: one sample (the paper); integrated: samplesPerSegment equal
    // sub-segments, 0 = one per grid spacing the segment spans
    collision_.samples =
        sampling == "midpoint"
      ? 1
      : int(getLabelInRange(collisionDict, "samplesPerSegment", 0, 0, 1000));
}


void Foam::functionObjects::dropletFiberCollision::reportSettings() const
{
    const auto& g = gridSpec_;
    Info<< type() << " " << name() << ":" << nl
        << "    clouds: ";
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
             : " (gather direct: kinematic parcel types read directly)"
           ) << nl;
    Info<< "    grid: (" << g.lower.x() << ' ' << g.lower.y() << ' ' << g.lower.z()
        << ") to (" << g.upper.x() << ' ' << g.upper.y() << ' ' << g.upper.z()
        << "), nodes (" << g.nodes[0] << ' ' << g.nodes[1] << ' ' << g.nodes[2]
        << "), averagingSteps " << averagingSteps_
        << ", beta " << kernel_.beta
        << ", rMaxCap " << kernel_.rMaxCap
        << ", cloudInCellBelow " << kernel_.cloudInCellBelow
        << ", negligibleWeight " << kernel_.negligibleWeight
        << ", vectorised " << Switch(kernel_.vectorised).c_str()
        << (
               grid_->batchedKernel()
             ? " (node weights: batched AVX2 + FMA)"
             : kernel_.vectorised
             ? " (node weights: per node, this CPU has no AVX2 + FMA)"
             : " (node weights: per node)"
           )
        << ", radiusAverage "
        << (collision_.radiusAverage == ::dropletFiber::RadiusAverage::Number
            ? "number" : "mass") << nl
        << "    collision: samples per segment " << collision_.samples
        << " (1: midpoint, 0: one per grid spacing)" << nl;
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
    air_->report(Info);
    const auto& s = solverSettings_;
    Info<< "    fibers: gravity (" << s.gravity.x() << ' ' << s.gravity.y() << ' '
        << s.gravity.z() << "), drag "
        << ::dropletFiber::dragModelName(s.drag.model).c_str()
        << ", theta " << s.theta << ", injectors " << label(injectors_.size())
        << ", fibers now " << label(fibers_.size()) << nl
        << "    output: writeVtk " << writeVtk_ << ", writeGridVtk "
        << writeGridVtk_ << nl << endl;
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
            FatalIOErrorInFunction(dict_)
                << "Cloud '" << cloudName << "' named in entry 'clouds' of "
                << type() << " '" << name() << "' does not exist at time "
                << time_.timeName() << "." << nl
                << "    Clouds that exist: " << available << nl
                << "    (A cloud created by another function object exists "
                << "from the first time step on, wherever it is listed.)"
                << exit(FatalIOError);
        }
    }
    return cloudNames_;
}


void Foam::functionObjects::dropletFiberCollision::gatherParcels()
{
    parcels_.clear();
    for (const word& cloudName : selectClouds())
    {
        parcels_.append
        (
            mesh_.lookupObject<cloud>(cloudName), dict_, gatherWriteObjects_
        );
    }
}


::dropletFiber::StepStatistics
Foam::functionObjects::dropletFiberCollision::depositParcels(const scalar dt)
{
    ::dropletFiber::DensityGrid& grid = *grid_;
    for (label i = 0; i < parcels_.size(); ++i)
    {
        ::dropletFiber::Parcel p;
        p.position = dropletFiber::toEigen(parcels_.position[i]);
        p.velocity = dropletFiber::toEigen(parcels_.U[i]);
        p.diameter = parcels_.d[i];
        p.nParticle = parcels_.nParticle[i];
        p.rhoDroplet = parcels_.rho[i];
        try
        {
            grid.deposit(p, dt);
        }
        catch (const std::exception& e)
        {
            // A parcel with NaN or negative values: a broken cloud, not ours
            FatalErrorInFunction
                << type() << " " << name() << ": parcel " << i
                << " at " << parcels_.position[i] << " cannot be deposited: "
                << e.what() << exit(FatalError);
        }
    }

    // Sum the step's accumulation across processors, over the union of the
    // boxes of nodes the processors touched only
    if (Pstream::parRun())
    {
        // The union of the processors' boxes in one reduction: max of
        // (-lo, hi) (an empty box contributes nothing)
        ::dropletFiber::IndexBox box = grid.stepBox();
        List<label> bounds(6, labelMin);
        if (!box.empty())
        {
            for (label d = 0; d < 3; ++d)
            {
                bounds[d] = -box.lo[d];
                bounds[3 + d] = box.hi[d];
            }
        }
        Pstream::listCombineGather(bounds, maxEqOp<label>());
        Pstream::listCombineScatter(bounds);
        if (bounds[0] == labelMin)
        {
            box = ::dropletFiber::IndexBox{};
        }
        else
        {
            for (label d = 0; d < 3; ++d)
            {
                box.lo[d] = -bounds[d];
                box.hi[d] = bounds[3 + d];
            }
        }
        if (!box.empty())
        {
            // Packed straight into the message and read back from it
            List<scalar> values
            (
                label(box.nodeCount()*::dropletFiber::nQuantities)
            );
            grid.packStep(box, values.data());
            Pstream::listCombineGather(values, plusEqOp<scalar>());
            Pstream::listCombineScatter(values);
            grid.unpackStep(box, values.cdata(), std::size_t(values.size()));
        }
    }

    // This step's statistics, summed over processors (every member is a sum)
    ::dropletFiber::StepStatistics stats = grid.stepStatistics();
    grid.commitStep();
    // One reduction for the four sums (the count is exact in a double)
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
    const label capped = label(sums[3]);
    stats.parcelsCapped = capped;

    if (capped > 0 && totals_.parcelsCapped == 0)
    {
        WarningInFunction
            << type() << " " << name() << ": the influence radius of "
            << capped << " parcels was capped at rMaxCap = " << kernel_.rMaxCap
            << " m at time " << time_.timeName() << nl
            << "    (warned once; the count is reported at write times)" << endl;
    }
    totals_.parcelsCapped += capped;
    return stats;
}


void Foam::functionObjects::dropletFiberCollision::injectFibers(const scalar t)
{
    for (auto& injector : injectors_)
    {
        for (auto& fiber : injector.inject(t))
        {
            totals_.fiberMassAdded += fiber.totalMass();
            fibers_.push_back(std::move(fiber));
            fiberOrigin_.push_back(injector.spec().name);
        }
    }
}


::dropletFiber::CaptureSources
Foam::functionObjects::dropletFiberCollision::collide(const scalar dt) const
{
    ::dropletFiber::CaptureSources capture(fibers_.size());
    for (std::size_t f = 0; f < fibers_.size(); ++f)
    {
        const ::dropletFiber::Fiber& fiber = fibers_[f];
        const Eigen::Matrix3Xd& x = fiber.positions();
        const Eigen::Matrix3Xd& v = fiber.velocities();
        capture[f].resize(fiber.segmentCount());
        // The fibers of other processors: their masses come with their
        // states after the step (fiberDistribution)
        if (!dropletFiber::fiberDistribution::advancesHere(f))
        {
            continue;
        }
        for (Eigen::Index j = 0; j < fiber.segmentCount(); ++j)
        {
            const Eigen::Vector3d segmentVelocity = 0.5*(v.col(j) + v.col(j + 1));
            const ::dropletFiber::SegmentCollision c =
                ::dropletFiber::collisionMass
                (
                    *grid_,
                    x.col(j),
                    x.col(j + 1),
                    fiber.material().radius,
                    segmentVelocity,
                    dt,
                    collision_
                );
            capture[f][j].mass = c.mass;
            capture[f][j].momentum = c.momentum;
        }
    }
    return capture;
}


void Foam::functionObjects::dropletFiberCollision::removeLostFibers()
{
    const boundBox& box = mesh_.bounds();
    std::size_t kept = 0;
    for (std::size_t f = 0; f < fibers_.size(); ++f)
    {
        const Eigen::Matrix3Xd& x = fibers_[f].positions();
        bool anyInside = false;
        for (Eigen::Index i = 0; i < x.cols() && !anyInside; ++i)
        {
            anyInside = box.contains(point(x(0, i), x(1, i), x(2, i)));
        }
        if (anyInside)
        {
            if (kept != f)
            {
                fibers_[kept] = std::move(fibers_[f]);
                fiberOrigin_[kept] = fiberOrigin_[f];
            }
            ++kept;
        }
        else
        {
            totals_.fiberMassRemoved += fibers_[f].totalMass();
            ++totals_.fibersRemoved;
        }
    }
    fibers_.erase(fibers_.begin() + kept, fibers_.end());
    fiberOrigin_.resize(kept);
}


Foam::scalar Foam::functionObjects::dropletFiberCollision::fiberMass() const
{
    scalar m = 0;
    for (const auto& fiber : fibers_)
    {
        m += fiber.totalMass();
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
    writeFile(mesh_, name, "dropletFiber", dict),
    dict_(dict),
    cloudNames_(),
    gatherWriteObjects_(false),
    lastTimeIndex_(-1),
    parcels_(),
    averagingSteps_(1),
    writeVtk_(true),
    writeGridVtk_(true)
{
    read(dict);

    // Fibers: from the restart state of the start time, else from the
    // dictionary
    if (!readState())
    {
        const dictionary fibersDict = dict.subOrEmptyDict("fibers");
        for (auto& named : dropletFiber::readFixedFibers(fibersDict))
        {
            totals_.fiberMassAdded += named.fiber.totalMass();
            fibers_.push_back(std::move(named.fiber));
            fiberOrigin_.push_back(named.name);
        }
    }

    const fileName vtkDir = baseFileDir()/name/time_.timeName(time_.startTime().value());
    if (Pstream::master() && (writeVtk_ || writeGridVtk_))
    {
        mkDir(vtkDir);
    }
    fibersSeries_.reset(new ::dropletFiber::SeriesFile(vtkDir/"fibers.vtp.series"));
    gridSeries_.reset(new ::dropletFiber::SeriesFile(vtkDir/"grid.vti.series"));
    fibersSeries_->load(time_.value() + 0.5*time_.deltaTValue());
    gridSeries_->load(time_.value() + 0.5*time_.deltaTValue());

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
    fvMeshFunctionObject::read(dict);
    // More digits than OpenFOAM's default: the table is compared across runs
    dictionary fileDict(dict);
    if (!fileDict.found("writePrecision"))
    {
        fileDict.add("writePrecision", 10);
    }
    writeFile::read(fileDict);
    dict_ = dict;

    cloudNames_ = dict.lookupOrDefault<wordList>("clouds", wordList());
    // direct: the kinematic parcel types read parcel by parcel, others through
    // cloud::writeObjects; writeObjects: every cloud that way (the same values)
    gatherWriteObjects_ =
        dropletFiber::getChoice
        (
            dict, "gather", "direct", {"direct", "writeObjects"}
        ) == "writeObjects";
    readGrid(dict);
    readCollision(dict);
    air_.reset
    (
        new dropletFiber::airSampler(mesh_, dict.subOrEmptyDict("air"))
    );

    const dictionary fibersDict = dict.subOrEmptyDict("fibers");
    solverSettings_ = dropletFiber::readFiberSolverSettings(fibersDict, time_);
    solver_.reset(new ::dropletFiber::FiberSolver(solverSettings_));

    writeVtk_ = dropletFiber::getSwitch(dict, "writeVtk", true);
    writeGridVtk_ = dropletFiber::getSwitch(dict, "writeGridVtk", true);

    // The grid and the injectors carry state: built once (a change of these
    // settings needs a new run)
    if (!grid_)
    {
        grid_.reset
        (
            dropletFiber::checkedCoreCall
            (
                dict,
                [this]()
                {
                    return new ::dropletFiber::DensityGrid
                    (
                        gridSpec_, kernel_, int(averagingSteps_)
                    );
                }
            )
        );
        for (const auto& spec : dropletFiber::readFiberInjectors(fibersDict))
        {
            injectors_.emplace_back(spec);
        }
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
    const scalar t = time_.value();
    const scalar dt = time_.deltaTValue();

    // 1. The parcels of this step, on this processor
    clockValue depositionStart(true);
    gatherParcels();
    const label nParcels = returnReduce(parcels_.size(), sumOp<label>());
    const scalar nDroplets = returnReduce(parcels_.nDroplets(), sumOp<scalar>());

    // 2. Onto the grid; summed across processors; averaged over the window
    const ::dropletFiber::StepStatistics deposit = depositParcels(dt);
    totals_.parcelMass += deposit.massIn;
    totals_.deposited += deposit.massDeposited;
    totals_.outside += deposit.massOutside;
    const scalar depositionTime = depositionStart.elapsed();

    // 3. New fibers
    clockValue fiberStart(true);
    injectFibers(t);

    // 4. Stochastic collision mass of every segment, from the grid (in
    //    parallel: of the fibers this processor advances)
    ::dropletFiber::CaptureSources capture = collide(dt);

    // 5. Advance the fibers: capture, air drag, bending, inextensibility;
    //    afterwards every processor holds every fiber and its capture
    const ::dropletFiber::StepReport report = advanceFibers(dt, capture);
    scalar capturedStep = 0;
    for (const auto& fiberCapture : capture)
    {
        for (const auto& segment : fiberCapture)
        {
            capturedStep += segment.mass;
        }
    }
    totals_.captured += capturedStep;

    // 6. Fibers that left
    removeLostFibers();
    const scalar fiberTime = fiberStart.elapsed();

    // 7. Report
    Log << type() << " " << name() << ": parcels " << nParcels
        << ", fibers " << label(fibers_.size())
        << ", captured " << capturedStep << " kg (total " << totals_.captured
        << " kg), segment-length error " << report.maxSegmentLengthError
        << ", sub-steps " << report.subSteps << endl;

    if (writeToFile())
    {
        OFstream& os = file();
        writeCurrentTime(os);
        os  << tab << label(fibers_.size())
            << tab << nParcels
            << tab << nDroplets
            << tab << deposit.massIn
            << tab << deposit.massDeposited
            << tab << deposit.massOutside
            << tab << capturedStep
            << tab << totals_.captured
            << tab << fiberMass()
            << tab << report.maxSegmentLengthError
            << tab << depositionTime
            << tab << fiberTime
            << endl;
    }

    if (time_.writeTime())
    {
        writeState();
        const scalar balance =
            totals_.fiberMassAdded + totals_.captured
          - totals_.fiberMassRemoved - fiberMass();
        Info<< type() << " " << name() << " conservation at time "
            << time_.timeName() << ", summed over all steps so far:" << nl
            << "    parcel mass " << totals_.parcelMass << " kg = on grid "
            << totals_.deposited << " + outside it " << totals_.outside
            << " (balance "
            << totals_.parcelMass - totals_.deposited - totals_.outside
            << " kg)" << nl
            << "    fiber mass " << fiberMass() << " kg = added "
            << totals_.fiberMassAdded << " + captured " << totals_.captured
            << " - removed " << totals_.fiberMassRemoved
            << " (balance " << balance << " kg)" << nl
            << "    parcel-steps with the influence radius capped at rMaxCap: "
            << totals_.parcelsCapped << nl << endl;
    }

    return true;
}


bool Foam::functionObjects::dropletFiberCollision::write()
{
    writeVtkFiles();
    return true;
}

// ************************************************************************* //
