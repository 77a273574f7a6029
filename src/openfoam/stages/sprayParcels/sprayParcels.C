/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The spray's parcels: which clouds, gathered how, each step's parcels as
    the grid takes them.

\*---------------------------------------------------------------------------*/

#include "sprayParcels.H"
#include "dictionaryChecks.H"
#include "plausibility.H"
#include "fiberStateIO.H"
#include "cloud.H"
#include "PstreamReduceOps.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dropletFiber::sprayParcels::sprayParcels
(
    const functionObject& owner,
    const fvMesh& mesh
)
:
    couplingStage(owner, mesh),
    gatherWriteObjects_(false),
    removalRestored_(false),
    checkedDroplets_(false),
    depletion_(true)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::dropletFiber::sprayParcels::cloudEnd(const label k) const
{
    return k + 1 < stepClouds_.size() ? cloudStarts_[k + 1] : parcels_.size();
}


void Foam::dropletFiber::sprayParcels::warnImplausibleDroplets()
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
    const auto& range = dropletDensityRange;
    const string text = implausible(lo < range.lo ? lo : hi, range);
    if (!text.empty())
    {
        WarningInFunction
            << type() << " " << name() << ": the droplet density (the"
            << " parcels' rho: the clouds' constantProperties rho0 or their"
            << " injection data) "
            << text.c_str() << endl;
    }
}


void Foam::dropletFiber::sprayParcels::logCloudRoute(const cloud& c)
{
    if (!loggedClouds_.insert(c.name()))
    {
        return;
    }
    const bool direct =
        !gatherWriteObjects_ && cloudParcels::readsDirectly(c);
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
    if (depletion_ && !cloudParcels::readsDirectly(c))
    {
        Info<< "; the droplets the fibers capture cannot be removed from"
            << " its parcels";
    }
    Info<< nl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dropletFiber::sprayParcels::read
(
    const dictionary& dict,
    const bool depletion
)
{
    dict_ = dict;
    depletion_ = depletion;
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
        getChoice
        (
            dict, "gather", "direct", {"direct", "writeObjects"}
        ) == "writeObjects";
}


Foam::wordList Foam::dropletFiber::sprayParcels::selectClouds() const
{
    if (cloudNames_.empty())
    {
        return cloudParcels::cloudNames(mesh_);
    }

    // One look-up per named cloud (the sorted list of all clouds only for
    // the error message: building it every step was measurable)
    for (const word& cloudName : cloudNames_)
    {
        if (!mesh_.foundObject<cloud>(cloudName))
        {
            const wordList available = cloudParcels::cloudNames(mesh_);
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


const std::vector<::dropletFiber::Parcel>&
Foam::dropletFiber::sprayParcels::gather()
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
    warnImplausibleDroplets();
    parcelsAll_ = returnReduce(parcels_.size(), sumOp<label>());
    dropletsAll_ = returnReduce(parcels_.nDroplets(), sumOp<scalar>());

    // As the grid takes them (the same values)
    stepParcels_.clear();
    for (label i = 0; i < parcels_.size(); ++i)
    {
        ::dropletFiber::Parcel& p = stepParcels_.emplace_back();
        p.position = toEigen(parcels_.position[i]);
        p.velocity = toEigen(parcels_.U[i]);
        p.diameter = parcels_.d[i];
        p.nParticle = parcels_.nParticle[i];
        p.rhoDroplet = parcels_.rho[i];
    }
    return stepParcels_;
}


Foam::wordList Foam::dropletFiber::sprayParcels::stepColumns() const
{
    wordList columns{"parcels", "droplets"};
    if (depletion_)
    {
        columns.append(wordList{"sprayedMass", "evaporatedMass", "escapedMass"});
        for (const word& species : liquidSpecies_)
        {
            columns.append("captured_" + species);
        }
    }
    return columns;
}


void Foam::dropletFiber::sprayParcels::addStepFigures(stepFigures& step)
{
    step.addCount("parcels", parcelsAll_);
    step.add("droplets", dropletsAll_);
    if (!depletion_)
    {
        return;
    }
    const cloudParcels::massReport& m = readCloudMassReport();
    step.add("sprayedMass", m.sprayed);
    step.add("evaporatedMass", m.evaporated);
    step.add("escapedMass", m.escaped);
    forAll(liquidSpecies_, i)
    {
        step.add("captured_" + liquidSpecies_[i], capturedSpecies_[i]);
    }
}


void Foam::dropletFiber::sprayParcels::report(Ostream& os) const
{
    os  << "    clouds: ";
    if (cloudNames_.empty())
    {
        os  << "all";
    }
    else
    {
        os  << cloudNames_;
    }
    os  << (
               gatherWriteObjects_
             ? " (gather writeObjects: every cloud through cloud::writeObjects)"
             : " (gather direct: the stock solvers' parcel types read directly,"
               " parcel by parcel: kinematic, colliding, MPPIC, thermo, reacting,"
               " spray clouds; others through cloud::writeObjects; each cloud's"
               " route is logged when first read)"
           ) << nl;
}


//- The function object's entries the spray reads
static const Foam::wordList sprayKeys
{
    "clouds", "gather"
};


Foam::wordList Foam::dropletFiber::sprayParcels::entries()
{
    return sprayKeys;
}


// ************************************************************************* //
