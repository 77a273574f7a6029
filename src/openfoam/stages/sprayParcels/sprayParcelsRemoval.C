/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    Depletion's write-back (docs/model.md sec. 7, P14): each parcel loses
    the fraction c_p of its droplets that the fibers captured (nParticle is
    reduced, a parcel with c_p = 1 is removed from its cloud; droplet size
    and velocity are unchanged). Clouds of the stock solvers' parcel types
    are written back; others are read through cloud::writeObjects only and
    cannot be: they keep their droplets, with a warning naming them.

    The clouds' files at a write time hold the parcels as they were before
    that step's removal (OpenFOAM writes them before the function objects
    execute), so the removal goes with the restart state, by parcel
    identity, and a restarted run applies it before its first step.

\*---------------------------------------------------------------------------*/

#include "sprayParcels.H"
#include "dictionaryChecks.H"
#include "cloud.H"
#include "PstreamReduceOps.H"

#include <unordered_map>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::dropletFiber::sprayParcels::writeBackToClouds
(
    std::vector<double>& fraction
)
{
    scalar kept = 0;
    forAll(stepClouds_, k)
    {
        const label start = cloudStarts_[k];
        const label end = cloudEnd(k);
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
            cloudParcels::depleteKinematic
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


void Foam::dropletFiber::sprayParcels::keepRemoval
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


void Foam::dropletFiber::sprayParcels::restoreRemoval
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


void Foam::dropletFiber::sprayParcels::applyRestoredRemoval()
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
            removal[cloudParcels::removalKey
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
            found += cloudParcels::applyRemoval
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


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::dropletFiber::parcelRemoval Foam::dropletFiber::sprayParcels::writeBack
(
    const std::vector<double>& captured
)
{
    std::vector<double> fraction = captured;
    addCapturedSpecies(fraction);
    parcelRemoval removal;
    removal.kept = writeBackToClouds(fraction);
    keepRemoval(fraction);
    // What left the parcels written back, and what flies on
    for (std::size_t p = 0; p < stepParcels_.size(); ++p)
    {
        const scalar m = ::dropletFiber::parcelMass(stepParcels_[p]);
        removal.removed += fraction[p]*m;
        removal.airborne += fraction[p] >= 1 ? 0 : (1 - fraction[p])*m;
    }
    return removal;
}


void Foam::dropletFiber::sprayParcels::applyRestoredRemovalOnce()
{
    if (removalRestored_)
    {
        coreCall
        (
            "removing the droplets captured before the restart",
            [this]() { applyRestoredRemoval(); }
        );
    }
}


void Foam::dropletFiber::sprayParcels::applyRemovalBeforeFirstStep()
{
    // In the run that wrote the state the removal came before the clouds'
    // next step; the first execute comes after it (droplets left in would
    // evaporate, or drive the gas, for a step). Clouds that do not exist
    // yet (made by a function object constructed later) get it then.
    bool exist = removalRestored_ && !cloudNames_.empty();
    for (const word& cloudName : cloudNames_)
    {
        exist = exist && mesh_.foundObject<cloud>(cloudName);
    }
    if (exist)
    {
        coreCall
        (
            "removing the droplets captured before the restart",
            [this]() { applyRestoredRemoval(); }
        );
    }
}


void Foam::dropletFiber::sprayParcels::writeState
(
    const fileName&,
    dictionary& state,
    dictionary& totals
)
{
    dictionary species;
    forAll(liquidSpecies_, i)
    {
        species.add(liquidSpecies_[i], capturedSpecies_[i]);
    }
    totals.add("capturedSpecies", species);
    // Depletion: the last step's removal, which the clouds' files of this
    // time do not hold yet
    if (depletion_)
    {
        dictionary removal;
        removal.add("origProc", removalProc_);
        removal.add("origId", removalId_);
        removal.add("fraction", removalFraction_);
        state.add("depletionRemoval", removal);
    }
}


void Foam::dropletFiber::sprayParcels::readState
(
    const dictionary& state,
    const fileName&
)
{
    // Per liquid species (a state without them: none captured)
    const dictionary& species =
        state.subDict("totals").subOrEmptyDict("capturedSpecies");
    const scalar none = 0;
    forAll(liquidSpecies_, i)
    {
        capturedSpecies_[i] =
            getCheckedScalar
            (
                species, liquidSpecies_[i], &none,
                [](scalar v) { return v >= 0; }, ">= 0"
            );
    }
    if (state.found("depletionRemoval"))
    {
        restoreRemoval(state.subDict("depletionRemoval"));
    }
}


// ************************************************************************* //
