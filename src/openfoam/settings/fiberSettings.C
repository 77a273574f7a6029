/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "fiberSettings.H"
#include "dictionaryChecks.H"
#include "dictionaryKeys.H"
#include "fiberStateIO.H"
#include "uniformDimensionedFields.H"
#include "IOobject.H"
#include "IFstream.H"
#include "vectorList.H"
#include "OStringStream.H"

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

using Foam::wordList;

//- The material entries, of fibers and of each injector and fixed fiber:
//  read by readFiberMaterial
const wordList materialKeys{"radius", "density", "youngsModulus"};

//- The entries of fibers the fibers' motion reads besides the material:
//  readFiberSolverSettings (points also readFiberInjectors' default) and
//  readFiberTurbulence (turbulenceSettings.H). The other stages' entries of
//  fibers are in their own lists (the function object joins them)
const wordList fiberSolverKeys
{
    "gravity", "drag", "normalDragCoefficient", "tangentialDragCoefficient",
    "maxSubSteps", "theta", "points", "turbulence"
};

//- The entries of an injector besides the material: read by readFiberInjectors
const wordList injectorKeys
{
    "position", "direction", "velocity", "length", "rate", "startTime",
    "endTime", "points", "represents", "massFlowRate"
};

//- The entries of a fixed fiber besides the material: read by readFixedFibers
const wordList fixedFiberKeys{"points", "hold", "represents"};


//- checkKeys for each sub-dictionary of fibersDict.listName
void checkEachKeys
(
    const Foam::dictionary& fibersDict,
    const Foam::word& listName,
    const wordList& allowed
)
{
    const Foam::dictionary* listPtr =
        Foam::dropletFiber::findSubDict(fibersDict, listName);
    if (!listPtr)
    {
        return;
    }
    for (const Foam::entry& e : *listPtr)
    {
        // An entry that is no dictionary is stopped by its reader
        if (e.isDict())
        {
            Foam::dropletFiber::checkKeys(e.dict(), allowed);
        }
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * //

Foam::wordList Foam::dropletFiber::fiberMotionKeys()
{
    return joinedKeys(materialKeys, fiberSolverKeys);
}


void Foam::dropletFiber::checkFiberSourceKeys(const dictionary& fibersDict)
{
    checkEachKeys(fibersDict, "injectors", joinedKeys(materialKeys, injectorKeys));
    checkEachKeys(fibersDict, "fixed", joinedKeys(materialKeys, fixedFiberKeys));
}


::dropletFiber::FiberMaterial Foam::dropletFiber::readFiberMaterial
(
    const dictionary& dict,
    const ::dropletFiber::FiberMaterial* defaults
)
{
    ::dropletFiber::FiberMaterial m;
    m.radius = getPositive(dict, "radius", defaults ? defaults->radius : -1);
    m.density = getPositive(dict, "density", defaults ? defaults->density : -1);
    if (!defaults && !dict.found("youngsModulus"))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'youngsModulus' is required: Young's modulus of the "
            << "fibers [Pa], >= 0 (0: limp fibers)." << exit(FatalIOError);
    }
    m.youngsModulus =
        getNonNegative
        (
            dict,
            "youngsModulus",
            defaults ? defaults->youngsModulus : 0
        );
    return m;
}


::dropletFiber::FiberSolverSettings Foam::dropletFiber::readFiberSolverSettings
(
    const dictionary& fibersDict,
    const Time& runTime
)
{
    ::dropletFiber::FiberSolverSettings s;

    // Gravity: the entry, else the case's constant/g, else none
    vector g(Zero);
    if (fibersDict.found("gravity"))
    {
        g = fibersDict.get<vector>("gravity");
    }
    else
    {
        IOobject gIO
        (
            "g",
            runTime.constant(),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        );
        if (gIO.typeHeaderOk<uniformDimensionedVectorField>(true))
        {
            g = uniformDimensionedVectorField(gIO).value();
        }
    }
    s.gravity = dropletFiber::toEigen(g);

    const word drag =
        getChoice
        (
            fibersDict,
            "drag",
            "slenderBodyOseen",
            {"none", "linear", "slenderBodyStokes", "slenderBodyOseen"}
        );
    s.drag.model = ::dropletFiber::dragModelFromName(drag);
    if (drag == "linear")
    {
        s.drag.normalCoefficient =
            getNonNegative(fibersDict, "normalDragCoefficient", 0);
        s.drag.tangentialCoefficient =
            getNonNegative(fibersDict, "tangentialDragCoefficient", 0);
        if (!fibersDict.found("normalDragCoefficient"))
        {
            FatalIOErrorInFunction(fibersDict)
                << "Entry 'normalDragCoefficient' is required with drag linear "
                << "(c_n [N s/m2], >= 0)." << exit(FatalIOError);
        }
    }

    s.maxSubSteps =
        int(getLabelInRange(fibersDict, "maxSubSteps", s.maxSubSteps, 1, 1000000));

    const scalar midpoint = 0.5;
    s.theta =
        getCheckedScalar
        (
            fibersDict, "theta", &midpoint,
            [](scalar t) { return t >= 0.5 && t <= 1; },
            "from 0.5 (implicit midpoint) to 1 (backward Euler)"
        );
    return s;
}


std::vector<::dropletFiber::FiberInjectorSpec>
Foam::dropletFiber::readFiberInjectors(const dictionary& fibersDict)
{
    std::vector<::dropletFiber::FiberInjectorSpec> specs;
    const dictionary* injectorsPtr = findSubDict(fibersDict, "injectors");
    if (!injectorsPtr)
    {
        return specs;
    }
    const ::dropletFiber::FiberMaterial defaults =
        readFiberMaterial(fibersDict, nullptr);
    const label defaultPoints =
        getLabelInRange(fibersDict, "points", 21, 2, 100000);

    for (const entry& e : *injectorsPtr)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(*injectorsPtr)
                << "Entry '" << e.keyword() << "' in 'injectors' is not a "
                << "dictionary: each injector is a sub-dictionary with "
                << "position, direction, velocity, length, rate."
                << exit(FatalIOError);
        }
        const dictionary& d = e.dict();
        ::dropletFiber::FiberInjectorSpec s;
        s.name = e.keyword();
        s.position = dropletFiber::toEigen(d.get<vector>("position"));
        s.direction = dropletFiber::toEigen(d.get<vector>("direction"));
        s.velocity = dropletFiber::toEigen(d.get<vector>("velocity"));
        s.length = getPositive(d, "length");
        s.rate = getPositive(d, "rate");
        s.startTime = d.lookupOrDefault<scalar>("startTime", 0);
        s.endTime = d.lookupOrDefault<scalar>("endTime", GREAT);
        s.points = getLabelInRange(d, "points", defaultPoints, 2, 100000);
        s.material = readFiberMaterial(d, &defaults);
        s.represents = readInjectorRepresents(d, s);
        checkedCoreCall(d, [&s]() { s.validate(); });
        specs.push_back(s);
    }
    return specs;
}


Foam::scalar Foam::dropletFiber::readInjectorRepresents
(
    const dictionary& d,
    const ::dropletFiber::FiberInjectorSpec& spec
)
{
    // Either the fibers each stands for, or the glass mass flow the stream
    // carries (the production figure), from which they follow
    if (!d.found("massFlowRate"))
    {
        return getPositive(d, "represents", 1);
    }
    if (d.found("represents"))
    {
        FatalIOErrorInFunction(d)
            << "Injector '" << spec.name.c_str() << "' has both 'represents' "
            << d.get<scalar>("represents") << " and 'massFlowRate' "
            << d.get<scalar>("massFlowRate") << ": give one (massFlowRate"
            << " sets represents = massFlowRate / (rate x one fiber's mass))."
            << exit(FatalIOError);
    }
    const scalar massFlowRate = getPositive(d, "massFlowRate");
    return ::dropletFiber::representsForMassFlow
    (
        massFlowRate, spec.rate, spec.length, spec.material
    );
}


std::vector<Foam::dropletFiber::namedFiber>
Foam::dropletFiber::readFixedFibers(const dictionary& fibersDict)
{
    std::vector<namedFiber> fibers;
    const dictionary* fixedPtr = findSubDict(fibersDict, "fixed");
    if (!fixedPtr)
    {
        return fibers;
    }
    const ::dropletFiber::FiberMaterial defaults =
        readFiberMaterial(fibersDict, nullptr);

    for (const entry& e : *fixedPtr)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(*fixedPtr)
                << "Entry '" << e.keyword() << "' in 'fixed' is not a "
                << "dictionary: each fixed fiber is a sub-dictionary with "
                << "points and hold." << exit(FatalIOError);
        }
        const dictionary& d = e.dict();
        const vectorList pts = d.get<vectorList>("points");
        if (pts.size() < 2)
        {
            FatalIOErrorInFunction(d)
                << "Entry 'points' has " << pts.size()
                << " points: a fiber needs at least 2." << exit(FatalIOError);
        }
        Eigen::Matrix3Xd x(3, pts.size());
        forAll(pts, i)
        {
            x.col(i) = dropletFiber::toEigen(pts[i]);
        }
        const ::dropletFiber::FiberMaterial material =
            readFiberMaterial(d, &defaults);
        const word hold =
            getChoice(d, "hold", "fixed", {"fixed", "clamped", "pinned", "free"});

        auto build = [&]() -> ::dropletFiber::Fiber
        {
            using ::dropletFiber::EndCondition;
            if (hold == "fixed")
            {
                return ::dropletFiber::Fiber::immobileFiber(x, material);
            }
            const EndCondition start =
                hold == "clamped" ? EndCondition::clampedEnd()
              : hold == "pinned" ? EndCondition::pinnedEnd()
              : EndCondition::freeEnd();
            return ::dropletFiber::Fiber(x, material, start);
        };
        ::dropletFiber::Fiber fiber = checkedCoreCall(d, build);
        fiber.setRepresents(getPositive(d, "represents", 1));
        fibers.push_back({e.keyword(), std::move(fiber)});
    }
    return fibers;
}


void Foam::dropletFiber::checkFiberSourcesUnchanged
(
    const dictionary& runningFibersDict,
    const dictionary& editedFibersDict
)
{
    // Compared as written (tokens, not layout or comments)
    auto entryText = [](const dictionary& dict, const word& key) -> string
    {
        const entry* e = dict.findEntry(key, keyType::LITERAL);
        if (!e)
        {
            return "no entry";
        }
        OStringStream os;
        if (e->isDict())
        {
            os << e->dict();
        }
        else
        {
            os << e->stream().toString();
        }
        return os.str();
    };
    for
    (
        const word key
      : {"radius", "density", "youngsModulus", "points", "injectors", "fixed"}
    )
    {
        const string running = entryText(runningFibersDict, key);
        const string edited = entryText(editedFibersDict, key);
        if (running != edited)
        {
            stopEditedEntry
            (
                editedFibersDict, key, running, edited,
                "The injectors count the fibers they gave and the fibers"
                " carry their material"
            );
        }
    }
}


// ************************************************************************* //
