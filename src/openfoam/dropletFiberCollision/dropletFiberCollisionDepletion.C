/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    Depletion (entry collision.depletion; docs/model.md sec. 7, P12-P14,
    P19): the mass the fibers capture in a step is taken from the parcels
    that carried it. After the collision samples (collide()):
      - each sample's mass m_s (eq. 9) is attributed to the corners of its
        cell in proportion to their part of the interpolated density (P12),
        by the corners' owners (gridBlocks::grantCapture), and gives the
        nodes their optical depth for the step (P13);
      - each parcel crosses the depths of the nodes its deposit reached and
        loses c_p = 1 - (1 - A_p) exp(-X_p) of its droplets (P14), its loss
        attributed to those nodes (P19; gridBlocks::removeCaptured);
      - each segment is given what its samples' nodes lost, its momentum
        that times the samples' droplet velocity;
      - written back (depleteParcels): nParticle is reduced, a parcel with
        c_p = 1 is removed from its cloud. Droplet size and velocity are
        unchanged.
    Mass captured = mass removed, to round-off. Clouds of the parcel types
    of the stock solvers (kinematic, colliding, MPPIC, thermo, reacting,
    reacting multiphase, heterogeneous reacting, spray: cloudParcels) are
    written back; other clouds are read through cloud::writeObjects only and
    cannot be: they keep their droplets, with a warning naming them.

\*---------------------------------------------------------------------------*/

#include "dropletFiberCollision.H"
#include "cloud.H"
#include "Time.H"
#include "fvMesh.H"
#include "PstreamReduceOps.H"
#include "dictionaryChecks.H"
#include "grid/MultilinearWeights.hpp"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

std::vector<double>
Foam::functionObjects::dropletFiberCollision::limitCapture
(
    const std::vector<::dropletFiber::DropletFieldValue>& fields,
    const std::vector<Eigen::Vector3d>& points,
    const std::vector<double>& massSums,
    const std::vector<double>& sampleMasses,
    const std::vector<int>& samplesPerSegment,
    const scalar dt,
    ::dropletFiber::CaptureSources& capture
)
{
    // m_s / Sigma per sample: its owners attribute it to their corners
    std::vector<double> shares(points.size(), 0.0);
    scalar demanded = 0;
    for (std::size_t s = 0; s < points.size(); ++s)
    {
        demanded += sampleMasses[s];
        if (sampleMasses[s] > 0 && massSums[s] > 0)
        {
            shares[s] = sampleMasses[s]/massSums[s];
        }
    }
    ::dropletFiber::CaptureLimitReport report;
    const std::vector<double> granted =
        blocks_->grantCapture
        (
            *grid_, points, shares, stepParcels_, dt, captureLimit_, report,
            stepCaptured_, parallelStatistics_
        );
    depletionStep_ = depletionSummary();
    depletionStep_.demanded = demanded;
    depletionStep_.nodesLimited = label(report.nodesLimited);
    // The core's CaptureLimit::granted, segment by segment
    std::size_t next = 0;
    std::size_t segment = 0;
    for (auto& fiberCapture : capture)
    {
        for (auto& segmentCapture : fiberCapture)
        {
            segmentCapture.mass = 0;
            segmentCapture.momentum.setZero();
            for (int s = 0; s < samplesPerSegment[segment]; ++s, ++next)
            {
                segmentCapture.mass += granted[next];
                segmentCapture.momentum += granted[next]*fields[next].velocity;
            }
            ++segment;
        }
    }
    // The demand where the limit bound (its granted part is the supply)
    if (report.nodesLimited > 0)
    {
        depletionStep_.limitedDemand = report.massDemanded - report.massGranted;
    }
    return granted;
}


::dropletFiber::IndexBox
Foam::functionObjects::dropletFiberCollision::fiberNodes() const
{
    // The fibers' bounding box, over every processor
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
    // The nodes of the cells it lies in: a sample's corners are its cell's
    // (axisCell, as multilinearWeights finds them)
    const ::dropletFiber::GridSpec& spec = gridSettings_.spec;
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


void Foam::functionObjects::dropletFiberCollision::depleteParcels
(
    const scalar dt
)
{
    // c_p of this processor's parcels, from limitCapture (the removal
    // came before the grants)
    std::vector<double> fraction = stepCaptured_;
    addCapturedSpecies(fraction);
    const scalar kept = writeBackToClouds(fraction);
    keepRemoval(fraction);
    // What left the parcels written back, and what flies on
    List<scalar> sums(6, Zero);
    sums[5] = kept;
    for (std::size_t p = 0; p < stepParcels_.size(); ++p)
    {
        const scalar m = ::dropletFiber::parcelMass(stepParcels_[p]);
        sums[0] += fraction[p]*m;
        sums[1] += fraction[p] >= 1 ? 0 : (1 - fraction[p])*m;
    }
    sums[2] = depletionStep_.demanded;
    sums[3] = scalar(depletionStep_.nodesLimited);
    sums[4] = depletionStep_.limitedDemand;
    Pstream::listCombineGather(sums, plusEqOp<scalar>());
    Pstream::listCombineScatter(sums);
    depletionStep_.removed = sums[0];
    depletionStep_.airborne = sums[1];
    depletionStep_.demanded = sums[2];
    depletionStep_.nodesLimited = label(sums[3]);
    depletionStep_.limitedDemand = sums[4];
    depletionStep_.kept = sums[5];
    logLimitOnce();
}


Foam::scalar Foam::functionObjects::dropletFiberCollision::writeBackToClouds
(
    std::vector<double>& fraction
)
{
    scalar kept = 0;
    forAll(stepClouds_, k)
    {
        const label start = cloudStarts_[k];
        const label end =
            k + 1 < stepClouds_.size() ? cloudStarts_[k + 1] : parcels_.size();
        bool taken = false;
        for (label p = start; p < end && !taken; ++p)
        {
            taken = fraction[p] > 0;
        }
        if (!taken)
        {
            continue;
        }
        // The function object only reads the clouds otherwise
        cloud& c =
            const_cast<cloud&>(mesh_.lookupObject<cloud>(stepClouds_[k]));
        if
        (
            dropletFiber::cloudParcels::depleteKinematic
            (
                c,
                fraction.data() + start,
                end - start,
                parcels_.address.size() == parcels_.size()
              ? parcels_.address.cdata() + start
              : nullptr
            )
        )
        {
            continue;
        }
        if (warnedUnwritable_.insert(c.name()))
        {
            WarningInFunction
                << type() << " " << name() << ": cloud '" << c.name()
                << "' (type " << c.type() << ") is read through"
                << " cloud::writeObjects only: the droplets the fibers"
                << " capture cannot be removed from its parcels, which fly"
                << " on unchanged (the captured mass is then counted twice;"
                << " the table's removedStep leaves it out). Use a cloud of"
                << " a stock solver (kinematic, colliding, MPPIC, thermo,"
                << " reacting, reacting multiphase, heterogeneous reacting,"
                << " spray), or collision.depletion false"
                << " (warned once per cloud, at time " << time_.timeName()
                << ")." << endl;
        }
        for (label p = start; p < end; ++p)
        {
            kept += fraction[p]*::dropletFiber::parcelMass(stepParcels_[p]);
        }
        std::fill(fraction.begin() + start, fraction.begin() + end, 0.0);
    }
    return kept;
}


void Foam::functionObjects::dropletFiberCollision::logLimitOnce()
{
    if (loggedLimit_ || depletionStep_.nodesLimited == 0)
    {
        return;
    }
    loggedLimit_ = true;
    Info<< type() << " " << name() << ": at time " << time_.timeName()
        << " the fibers asked more droplet mass of "
        << depletionStep_.nodesLimited << " grid nodes than this step's"
        << " parcels brought there (eq. 9 asked "
        << depletionStep_.limitedDemand << " kg more than they hold): their"
        << " capture is limited to what the nodes hold (docs/model.md sec. 7;"
        << " a large time step, a thin spray or fibers thicker than the grid"
        << " spacing). Logged once." << nl << endl;
}


void Foam::functionObjects::dropletFiberCollision::reportBinderBalance() const
{
    if (!depletion_)
    {
        return;
    }
    // Captured = removed + kept in clouds that cannot be written back
    const depletionSummary& d = depletionStep_;
    const scalar scale = max(mag(d.captured), mag(d.removed + d.kept));
    Info<< type() << " " << name() << " binder balance at time "
        << time_.timeName() << ":" << nl
        << "    this step: captured " << d.captured << " kg, removed from"
        << " the parcels " << d.removed << " kg";
    if (d.kept > 0)
    {
        Info<< ", left in the parcels of clouds read through"
            << " cloud::writeObjects " << d.kept << " kg (they cannot be"
            << " written back)";
    }
    Info<< " (relative difference "
        << (scale > 0 ? (d.captured - d.removed - d.kept)/scale : scalar(0))
        << "), eq. 9 before the limit " << d.demanded << " kg" << nl
        << "    airborne parcel mass after the removal " << d.airborne
        << " kg; captured in total " << totals_.captured << " kg" << nl
        << "    since this run started: eq. 9 asked " << depletionRun_.demanded
        << " kg, the fibers captured " << depletionRun_.captured
        << " kg and the parcels lost " << depletionRun_.removed
        << " kg; the limit bound in " << limitedSteps_ << " of "
        << depletionSteps_ << " steps" << nl << endl;
}

void Foam::functionObjects::dropletFiberCollision::keepRemoval
(
    const std::vector<double>& fraction
)
{
    removalProc_.clear();
    removalId_.clear();
    removalFraction_.clear();
    for (std::size_t p = 0; p < fraction.size(); ++p)
    {
        if (fraction[p] > 0 && parcels_.origId[p] >= 0)
        {
            removalProc_.append(parcels_.origProc[p]);
            removalId_.append(parcels_.origId[p]);
            removalFraction_.append(fraction[p]);
        }
    }
}


void Foam::functionObjects::dropletFiberCollision::restoreRemoval
(
    const dictionary& removal
)
{
    removalProc_ = removal.get<labelList>("origProc");
    removalId_ = removal.get<labelList>("origId");
    removalFraction_ = removal.get<scalarList>("fraction");
    if
    (
        removalId_.size() != removalProc_.size()
     || removalFraction_.size() != removalProc_.size()
    )
    {
        FatalIOErrorInFunction(removal)
            << "Entries 'origProc', 'origId' and 'fraction' of the restart"
            << " state's depletionRemoval have " << removalProc_.size()
            << ", " << removalId_.size() << " and "
            << removalFraction_.size() << " values: they must have as many."
            << exit(FatalIOError);
    }
    forAll(removalFraction_, i)
    {
        const scalar f = removalFraction_[i];
        if (!(f > 0 && f <= 1))
        {
            FatalIOErrorInFunction(removal)
                << "Entry 'fraction' of the restart state's depletionRemoval"
                << " is " << f << " at " << i << ": allowed are values in"
                << " (0, 1]." << exit(FatalIOError);
        }
    }
    removalRestored_ = true;
}


void Foam::functionObjects::dropletFiberCollision::applyRestoredRemoval()
{
    removalRestored_ = false;
    // Every processor's list: a parcel may have passed to another processor
    // in the cloud's step since the state was written
    List<labelList> procs(Pstream::nProcs());
    List<labelList> ids(Pstream::nProcs());
    List<scalarList> fractions(Pstream::nProcs());
    procs[Pstream::myProcNo()] = removalProc_;
    ids[Pstream::myProcNo()] = removalId_;
    fractions[Pstream::myProcNo()] = removalFraction_;
    Pstream::gatherList(procs);
    Pstream::scatterList(procs);
    Pstream::gatherList(ids);
    Pstream::scatterList(ids);
    Pstream::gatherList(fractions);
    Pstream::scatterList(fractions);
    std::unordered_map<std::int64_t, scalar> removal;
    forAll(procs, proci)
    {
        forAll(procs[proci], i)
        {
            removal[dropletFiber::cloudParcels::removalKey
            (
                procs[proci][i], ids[proci][i]
            )] = fractions[proci][i];
        }
    }
    label found = 0;
    if (depletion_ && !removal.empty())
    {
        for (const word& cloudName : selectClouds())
        {
            found += dropletFiber::cloudParcels::applyRemoval
            (
                const_cast<cloud&>(mesh_.lookupObject<cloud>(cloudName)),
                removal
            );
        }
    }
    Info<< type() << " " << name() << ": the droplets captured in the step"
        << " restarted from removed from "
        << returnReduce(found, sumOp<label>()) << " of "
        << label(removal.size()) << " parcels" << nl;
}

// ************************************************************************* //
