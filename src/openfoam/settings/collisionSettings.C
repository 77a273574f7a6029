/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "collisionSettings.H"
#include "dictionaryChecks.H"
#include "dictionaryKeys.H"

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- The entries of collision: read by readSamples and readCollisionSettings
const wordList collisionKeys
{
    "sampling", "samplesPerSegment", "radiusAverage", "depletion", "mode",
    "seed", "spread"
};

//- The entries of collision.spread: read by readSpreadSettings
const wordList spreadKeys{"active", "neighbours", "maxClustering", "maxSpacing"};


//- Sample points per segment: midpoint 1 (the paper); integrated:
//  samplesPerSegment equal sub-segments, 0 = one per grid spacing spanned
int readSamples(const dictionary& collisionDict)
{
    const word sampling =
        Foam::dropletFiber::getChoice
        (
            collisionDict, "sampling", "midpoint", {"midpoint", "integrated"}
        );
    return
        sampling == "midpoint"
      ? 1
      : int
        (
            Foam::dropletFiber::getLabelInRange
            (
                collisionDict, "samplesPerSegment", 0, 0, 1000
            )
        );
}


//- The dictionary radiusAverage is read from: collision, or grid (its old
//  place, with a warning); both stop the run
const dictionary& radiusAverageDict
(
    const dictionary& collisionDict,
    const dictionary& gridDict
)
{
    const bool inCollision = collisionDict.found("radiusAverage");
    const bool inGrid = gridDict.found("radiusAverage");
    if (inCollision && inGrid)
    {
        FatalIOErrorInFunction(gridDict)
            << "Entry 'radiusAverage' is given in both 'grid' and "
            << "'collision': give it in 'collision' only (a collision "
            << "option, the mean radius of eq. 9)." << exit(FatalIOError);
    }
    if (inGrid)
    {
        IOWarningInFunction(gridDict)
            << "Entry 'radiusAverage' in 'grid' is read from its old place:"
            << " move it to the 'collision' sub-dictionary (a collision"
            << " option, the mean radius of eq. 9)." << endl;
        return gridDict;
    }
    return collisionDict;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * //

::dropletFiber::CollisionOptions Foam::dropletFiber::readCollisionSettings
(
    const dictionary& dict
)
{
    const dictionary collisionDict = optionalSubDict(dict, "collision");
    const dictionary gridDict = optionalSubDict(dict, "grid");
    checkKeys(collisionDict, collisionKeys);
    ::dropletFiber::CollisionOptions options;
    options.samples = readSamples(collisionDict);
    const word radius =
        getChoice
        (
            radiusAverageDict(collisionDict, gridDict),
            "radiusAverage", "mass", {"number", "mass"}
        );
    options.radiusAverage =
        radius == "number"
      ? ::dropletFiber::RadiusAverage::Number
      : ::dropletFiber::RadiusAverage::Mass;
    // expected: eq. 9's mass every step (the paper); discrete: a Poisson
    // number of droplets of that mean (docs/model.md sec. 3, P30)
    const word mode =
        getChoice(collisionDict, "mode", "expected", {"expected", "discrete"});
    options.mode =
        mode == "discrete"
      ? ::dropletFiber::CollisionMode::Discrete
      : ::dropletFiber::CollisionMode::Expected;
    options.seed =
        std::uint32_t(getLabelInRange(collisionDict, "seed", 0, 0, labelMax));
    return options;
}


bool Foam::dropletFiber::readDepletion(const dictionary& dict)
{
    // true: the captured mass leaves the parcels (docs/model.md sec. 7);
    // false: the paper's behaviour, the spray unchanged by the fibers
    const dictionary collisionDict = optionalSubDict(dict, "collision");
    checkKeys(collisionDict, collisionKeys);
    return getSwitch(collisionDict, "depletion", true);
}


Foam::dropletFiber::spreadSettings Foam::dropletFiber::readSpreadSettings
(
    const dictionary& dict
)
{
    // The populations of weighted fibers (docs/model.md sec. 12): on by
    // default, each on the finest level where it is thin (clustering eps at
    // most maxClustering) or its kernel reaches `neighbours` other computed
    // fibers, levels up to maxSpacing (0: half the grid box's largest extent)
    const dictionary collisionDict = optionalSubDict(dict, "collision");
    const dictionary spreadDict = optionalSubDict(collisionDict, "spread");
    checkKeys(spreadDict, spreadKeys);
    spreadSettings settings;
    settings.active = getSwitch(spreadDict, "active", true);
    settings.neighbours = getPositive(spreadDict, "neighbours", 8);
    settings.maxClustering = getNonNegative(spreadDict, "maxClustering", 0.05);
    settings.maxSpacing = getNonNegative(spreadDict, "maxSpacing", 0);
    return settings;
}


Foam::word Foam::dropletFiber::collisionModeName
(
    const ::dropletFiber::CollisionMode mode
)
{
    return mode == ::dropletFiber::CollisionMode::Discrete ? "discrete" : "expected";
}


std::string Foam::dropletFiber::collisionModeReport
(
    const ::dropletFiber::CollisionOptions& options
)
{
    return
        options.mode == ::dropletFiber::CollisionMode::Discrete
      ? "discrete (Poisson droplet counts, seed "
      + std::to_string(options.seed) + ")"
      : "expected (eq. 9's mass every step)";
}


Foam::word Foam::dropletFiber::radiusAverageName
(
    const ::dropletFiber::RadiusAverage average
)
{
    return average == ::dropletFiber::RadiusAverage::Number ? "number" : "mass";
}

// ************************************************************************* //
