/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The coupling grid built, checked and reported; each step's deposit and
    the queries of the capture stage on it.

\*---------------------------------------------------------------------------*/

#include "couplingGrid.H"
#include "dictionaryChecks.H"
#include "plausibility.H"
#include "grid/MultilinearWeights.hpp"
#include "PstreamReduceOps.H"
#include "boundBox.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dropletFiber::couplingGrid::couplingGrid
(
    const functionObject& owner,
    const fvMesh& mesh
)
:
    couplingStage(owner, mesh),
    windowStateFormat_(::dropletFiber::DensityGrid::WindowStateFormat::Smaller),
    writeWindowValues_(false)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dropletFiber::couplingGrid::rebuildGrid
(
    const ::dropletFiber::WindowState* window
)
{
    grid_.reset();
    grid_.reset
    (
        new ::dropletFiber::DensityGrid
        (
            settings_.spec,
            settings_.kernel,
            int(settings_.averagingSteps),
            blocks_->block()
        )
    );
    if (window)
    {
        grid_->restoreWindow(*window);
    }
}


void Foam::dropletFiber::couplingGrid::depositOwnParcel
(
    const std::vector<::dropletFiber::Parcel>& parcels,
    const std::size_t i,
    const scalar dt
)
{
    try
    {
        grid_->deposit(parcels[i], dt);
    }
    catch (const std::exception& e)
    {
        // A parcel with NaN or negative values: a broken cloud, not ours
        const Eigen::Vector3d& x = parcels[i].position;
        FatalErrorInFunction
            << type() << " " << name() << ": parcel " << label(i)
            << " at " << point(x.x(), x.y(), x.z()) << " cannot be deposited: "
            << e.what() << exit(FatalError);
    }
}


::dropletFiber::StepStatistics
Foam::dropletFiber::couplingGrid::summedOverProcessors
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


void Foam::dropletFiber::couplingGrid::countCappedParcels(const label capped)
{
    if (capped > 0 && totals_.parcelsCapped == 0)
    {
        WarningInFunction
            << type() << " " << name() << ": the influence radius of "
            << capped << " parcels was capped at rMaxCap = "
            << settings_.kernel.rMaxCap
            << " m at time " << time_.timeName() << nl
            << "    (warned once; the count is reported at write times)" << endl;
    }
    totals_.parcelsCapped += capped;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dropletFiber::couplingGrid::readWindowOutput(const dictionary& dict)
{
    writeWindowValues_ = getSwitch(dict, "writeWindowValues", false);
    const word format = getChoice
    (
        dict, "windowState", "smaller", {"smaller", "parcels", "nodeValues"}
    );
    using Format = ::dropletFiber::DensityGrid::WindowStateFormat;
    windowStateFormat_ =
        format == "parcels" ? Format::DepositLog
      : format == "nodeValues" ? Format::NodeValues
      : Format::Smaller;
}


void Foam::dropletFiber::couplingGrid::build
(
    const dictionary& dict,
    const dictionary& gridDict,
    const gridSettings& settings,
    const std::vector<::dropletFiber::FiberInjectorSpec>& injectors
)
{
    settings_ = settings;
    blocks_.reset
    (
        checkedCoreCall
        (
            gridDict,
            [this]() { return new gridBlocks(mesh_, settings_.spec); }
        )
    );
    // The blocks first: the memory check counts the largest block's nodes
    const scalar deltaT = time_.deltaTValue();
    memory_ = estimateMemory
    (
        settings_, scalar(blocks_->largestBlockNodes()), injectors, deltaT
    );
    checkMemory(dict, memory_, injectors, deltaT);
    grid_.reset
    (
        checkedCoreCall
        (
            dict,
            [this]()
            {
                return new ::dropletFiber::DensityGrid
                (
                    settings_.spec,
                    settings_.kernel,
                    int(settings_.averagingSteps),
                    blocks_->block()
                );
            }
        )
    );
    depositReport_.reset
    (
        new depositReport(type() + " " + name(), settings_.spec, settings_.kernel)
    );
}


void Foam::dropletFiber::couplingGrid::read
(
    const dictionary& dict,
    const bool running,
    const std::vector<::dropletFiber::FiberInjectorSpec>& injectors
)
{
    readWindowOutput(dict);
    const dictionary& gridDict = optionalSubDict(dict, "grid");
    const gridSettings grid = readGridSettings(gridDict, mesh_);
    if (running)
    {
        checkUnchanged(grid, gridDict);
        return;
    }
    build(dict, gridDict, grid, injectors);
    // A unit slip runs, warned once at the start
    warnImplausibleSpacing(gridDict, settings_, mesh_);
}


void Foam::dropletFiber::couplingGrid::checkUnchanged
(
    const gridSettings& grid,
    const dictionary& gridDict
) const
{
    checkGridUnchanged(settings_, grid, gridDict);
}


void Foam::dropletFiber::couplingGrid::warnBoxOutsideMesh() const
{
    const boundBox& meshBox = mesh_.bounds();
    const auto& g = settings_.spec;
    const boundBox gridBox
    (
        point(g.lower.x(), g.lower.y(), g.lower.z()),
        point(g.upper.x(), g.upper.y(), g.upper.z())
    );
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
}


::dropletFiber::IndexBox Foam::dropletFiber::couplingGrid::nodesOfCellsIn
(
    const vector& lo,
    const vector& hi
) const
{
    const ::dropletFiber::GridSpec& spec = settings_.spec;
    ::dropletFiber::IndexBox box;
    for (direction d = 0; d < 3; ++d)
    {
        if (!(lo[d] <= hi[d]))
        {
            return ::dropletFiber::IndexBox();
        }
        if (spec.flat(d))
        {
            box.lo[d] = box.hi[d] = 0;
            continue;
        }
        if (hi[d] < spec.lower[d] || lo[d] > spec.upper[d])
        {
            return ::dropletFiber::IndexBox();
        }
        const scalar h = spec.spacing(d);
        box.lo[d] =
            ::dropletFiber::axisCell(lo[d], spec.lower[d], h, spec.nodes[d]).cell;
        box.hi[d] =
            ::dropletFiber::axisCell(hi[d], spec.lower[d], h, spec.nodes[d]).cell + 1;
    }
    return box;
}


::dropletFiber::StepStatistics Foam::dropletFiber::couplingGrid::deposit
(
    const std::vector<::dropletFiber::Parcel>& parcels,
    const scalar dt,
    const ::dropletFiber::IndexBox* keepNear,
    const bool discrete,
    parallelStatistics& statistics
)
{
    if (keepNear)
    {
        grid_->keepTablesNear(*keepNear);
    }
    using stage = parallelStatistics::stage;
    blocks_->depositCopies
    (
        *grid_, parcels, dt, statistics,
        [&](const std::size_t i) { depositOwnParcel(parcels, i, dt); },
        discrete
    );
    const ::dropletFiber::StepStatistics local = grid_->stepStatistics();
    const ::dropletFiber::StepStatistics& copies = grid_->copyStatistics();
    statistics.countDeposit
    (
        scalar(local.parcels),
        scalar(copies.parcels),
        scalar(local.nodesVisited + copies.nodesVisited)
    );
    statistics.timed(stage::deposit, [&]() { grid_->commitStep(); });
    const ::dropletFiber::StepStatistics stats = summedOverProcessors(local);
    countCappedParcels(label(stats.parcelsCapped));
    totals_.parcelMass += stats.massIn;
    totals_.deposited += stats.massDeposited;
    totals_.outside += stats.massOutside;
    return stats;
}


void Foam::dropletFiber::couplingGrid::recordDeposit
(
    const ::dropletFiber::StepStatistics& stats,
    const scalar wallTime
)
{
    lastDeposit_ = stats;
    depositReport_->record(stats, wallTime, time_.timeName());
}


void Foam::dropletFiber::couplingGrid::addStepFigures
(
    stepFigures& step
) const
{
    step.add("parcelMass", lastDeposit_.massIn);
    step.add("massOnGrid", lastDeposit_.massDeposited);
    step.add("massOutsideGrid", lastDeposit_.massOutside);
}


void Foam::dropletFiber::couplingGrid::reportConservation() const
{
    const depositTotals& t = totals_;
    Info<< "    parcel mass " << t.parcelMass << " kg = on grid "
        << t.deposited << " + outside it " << t.outside << " (balance "
        << t.parcelMass - t.deposited - t.outside << " kg)" << nl
        << "    parcel-steps with the influence radius capped at rMaxCap: "
        << t.parcelsCapped << nl;
}


std::vector<::dropletFiber::DropletFieldValue>
Foam::dropletFiber::couplingGrid::sample
(
    const std::vector<Eigen::Vector3d>& points,
    parallelStatistics& statistics,
    std::vector<double>* massSums
)
{
    return blocks_->sample(*grid_, points, statistics, massSums);
}


std::vector<double> Foam::dropletFiber::couplingGrid::grantCapture
(
    const std::vector<Eigen::Vector3d>& points,
    const std::vector<double>& shares,
    const std::vector<double>* interceptors,
    const std::vector<Eigen::Vector3d>& strips,
    const std::vector<::dropletFiber::Parcel>& parcels,
    const scalar dt,
    ::dropletFiber::CaptureLimitReport& report,
    std::vector<double>& captured,
    parallelStatistics& statistics,
    spreadStep* spread
)
{
    return blocks_->grantCapture
    (
        *grid_, points, shares, interceptors, strips, parcels, dt, report,
        captured, statistics, spread
    );
}


std::vector<double> Foam::dropletFiber::couplingGrid::realiseCapture
(
    const std::vector<::dropletFiber::Parcel>& parcels,
    const std::vector<double>& ratios,
    std::vector<double>& cut,
    bool& fellShort,
    parallelStatistics& statistics,
    spreadStep* spread
)
{
    return blocks_->realiseCapture
    (
        parcels, ratios, cut, fellShort, statistics, spread
    );
}


void Foam::dropletFiber::couplingGrid::report(Ostream& os) const
{
    const auto& g = settings_.spec;
    const auto& kernel = settings_.kernel;
    os  << "    grid: (" << g.lower.x() << ' ' << g.lower.y() << ' ' << g.lower.z()
        << ") to (" << g.upper.x() << ' ' << g.upper.y() << ' ' << g.upper.z()
        << "), nodes (" << g.nodes[0] << ' ' << g.nodes[1] << ' ' << g.nodes[2]
        << "), averagingSteps " << settings_.averagingSteps
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
           ) << nl;
}


void Foam::dropletFiber::couplingGrid::reportBlocks(Ostream& os) const
{
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
    blocks_->report(os);
}


void Foam::dropletFiber::couplingGrid::reportMemory
(
    Ostream& os,
    const scalar fiberPoints
) const
{
    Foam::dropletFiber::reportMemory(os, memory_, fiberPoints);
}


void Foam::dropletFiber::couplingGrid::reportAtWrite()
{
    depositReport_->reportAtWrite(time_.timeName());
}


//- The function object's entries the grid reads (grid's own: gridSettings.C)
static const Foam::wordList gridStageKeys
{
    "grid", "writeWindowValues", "windowState"
};


Foam::wordList Foam::dropletFiber::couplingGrid::entries()
{
    return gridStageKeys;
}


// ************************************************************************* //
