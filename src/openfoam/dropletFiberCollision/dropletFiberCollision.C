/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "dropletFiberCollision.H"
#include "cloud.H"
#include "Time.H"
#include "fvMesh.H"
#include "PstreamReduceOps.H"
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

Foam::wordList
Foam::functionObjects::dropletFiberCollision::selectClouds() const
{
    const wordList available = dropletFiber::cloudParcels::cloudNames(mesh_);

    if (cloudNames_.empty())
    {
        return available;
    }

    for (const word& cloudName : cloudNames_)
    {
        if (!available.found(cloudName))
        {
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
        parcels_.append(mesh_.lookupObject<cloud>(cloudName), dict_);
    }
}


void Foam::functionObjects::dropletFiberCollision::writeFileHeader
(
    Ostream& os
) const
{
    writeHeader(os, "Droplet-fiber coupling: parcels seen each time step");
    writeCommented(os, "Time");
    writeTabbed(os, "parcels");
    writeTabbed(os, "droplets");
    writeTabbed(os, "dropletMass[kg]");
    os  << endl;
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
    lastTimeIndex_(-1),
    parcels_()
{
    read(dict);
    if (writeToFile())
    {
        writeFileHeader(file());
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::dropletFiberCollision::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);
    dict_ = dict;

    cloudNames_ = dict.lookupOrDefault<wordList>("clouds", wordList());

    Info<< type() << " " << name() << ":" << nl
        << "    clouds: "
        << (cloudNames_.empty() ? string("all") : string(""))
        << (cloudNames_.empty() ? wordList() : cloudNames_) << nl
        << endl;

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

    gatherParcels();

    const label nParcels = returnReduce(parcels_.size(), sumOp<label>());
    const scalar nDroplets = returnReduce(parcels_.nDroplets(), sumOp<scalar>());
    const scalar mass = returnReduce(parcels_.totalMass(), sumOp<scalar>());

    Log << type() << " " << name() << ": parcels " << nParcels
        << ", droplets " << nDroplets
        << ", droplet mass " << mass << " kg" << endl;

    if (writeToFile())
    {
        OFstream& os = file();
        writeCurrentTime(os);
        os  << tab << nParcels << tab << nDroplets << tab << mass << endl;
    }

    return true;
}


bool Foam::functionObjects::dropletFiberCollision::write()
{
    return true;
}

// ************************************************************************* //
