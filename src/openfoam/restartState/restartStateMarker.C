/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "restartStateMarker.H"
#include "Time.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dropletFiber::restartStateMarker::restartStateMarker
(
    const Time& runTime,
    const word& stateName,
    std::function<bool()> stateFollows
)
:
    IOdictionary
    (
        IOobject
        (
            stateName + ".marker",
            runTime.timeName(),
            "uniform"/word("dropletFiber"),
            runTime,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        )
    ),
    stateFollows_(std::move(stateFollows))
{
    add("state", stateName);
    add("gridWindow", word(stateName + ".gridWindow"));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fileName Foam::dropletFiber::restartStateMarker::path
(
    const Time& runTime,
    const word& timeName,
    const word& stateName
)
{
    return runTime.path()/timeName/"uniform"/"dropletFiber"/(stateName + ".marker");
}


bool Foam::dropletFiber::restartStateMarker::writeObject
(
    IOstream::streamFormat fmt,
    IOstream::versionNumber ver,
    IOstream::compressionType cmp,
    const bool valid
) const
{
    if (!stateFollows_())
    {
        return true;
    }
    return IOdictionary::writeObject(IOstream::ASCII, ver, cmp, valid);
}

// ************************************************************************* //
