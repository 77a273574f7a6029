/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "restartSources.H"
#include "error.H"
#include "OStringStream.H"
#include "labelVector.H"
#include "vector.H"

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

bool sameDicts(const dictionary& a, const dictionary& b);

//- Whether two entries hold the same tokens (numbers as doubles) or the
//  same sub-dictionaries
bool sameEntries(const entry& a, const entry& b)
{
    if (a.isDict() || b.isDict())
    {
        return a.isDict() && b.isDict() && sameDicts(a.dict(), b.dict());
    }
    const ITstream& ta = a.stream();
    const ITstream& tb = b.stream();
    if (ta.size() != tb.size())
    {
        return false;
    }
    forAll(ta, i)
    {
        const bool numbers = ta[i].isNumber() && tb[i].isNumber();
        if
        (
            numbers ? ta[i].number() != tb[i].number() : !(ta[i] == tb[i])
        )
        {
            return false;
        }
    }
    return true;
}


bool sameDicts(const dictionary& a, const dictionary& b)
{
    if (a.size() != b.size())
    {
        return false;
    }
    for (const entry& e : a)
    {
        const entry* other = b.findEntry(e.keyword(), keyType::LITERAL);
        if (!other || !sameEntries(e, *other))
        {
            return false;
        }
    }
    return true;
}


//- The entries of two dictionaries that differ (or are in one only)
wordList differingKeys(const dictionary& a, const dictionary& b)
{
    DynamicList<word> keys;
    for (const entry& e : a)
    {
        const entry* other = b.findEntry(e.keyword(), keyType::LITERAL);
        if (!other || !sameEntries(e, *other))
        {
            keys.append(e.keyword());
        }
    }
    for (const entry& e : b)
    {
        if (!a.findEntry(e.keyword(), keyType::LITERAL))
        {
            keys.append(e.keyword());
        }
    }
    return wordList(keys);
}


//- The grid in force as a dictionary of numbers
dictionary gridDict(const Foam::dropletFiber::gridSettings& grid)
{
    const auto& g = grid.spec;
    const auto& k = grid.kernel;
    dictionary d;
    d.add("lower", vector(g.lower.x(), g.lower.y(), g.lower.z()));
    d.add("upper", vector(g.upper.x(), g.upper.y(), g.upper.z()));
    d.add("nodes", labelVector(g.nodes[0], g.nodes[1], g.nodes[2]));
    d.add("averagingSteps", grid.averagingSteps);
    d.add("beta", k.beta);
    d.add("rMaxCap", k.rMaxCap);
    d.add("cloudInCellBelow", k.cloudInCellBelow);
    d.add("negligibleWeight", k.negligibleWeight);
    return d;
}


//- Warn about the named sources (fixed fibers or injectors) that differ
void warnNamedDiffer
(
    const word& owner,
    const fileName& path,
    const word& what,
    const dictionary& saved,
    const dictionary& now,
    const string& used
)
{
    for (const word& name : differingKeys(saved, now))
    {
        const bool inSaved = saved.found(name);
        const bool inNow = now.found(name);
        OStringStream how;
        if (!inNow)
        {
            how << "is in the restart state's dictionary only";
        }
        else if (!inSaved)
        {
            how << "is new in this run's dictionary";
        }
        else
        {
            how << "differs in " << differingKeys(saved.subDict(name), now.subDict(name));
        }
        WarningInFunction
            << owner.c_str() << ": " << what.c_str() << " '" << name << "' "
            << how.str().c_str() << " (the restart state " << path
            << " against this run's dictionary): " << used.c_str() << "."
            << nl << "    Set 'restart fresh;' to start from the dictionary"
            << " alone (docs/userGuide.md, Restart)." << endl;
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::dictionary Foam::dropletFiber::restartSources
(
    const dictionary& fibersDict,
    const gridSettings& grid
)
{
    dictionary sources;
    sources.add("fixed", fibersDict.subOrEmptyDict("fixed"));
    sources.add("injectors", fibersDict.subOrEmptyDict("injectors"));
    sources.add("grid", gridDict(grid));
    return sources;
}


bool Foam::dropletFiber::sameSource
(
    const dictionary& saved,
    const dictionary& fibersDict,
    const word& what,
    const word& name
)
{
    // (subOrEmptyDict gives a copy: kept while its entries are compared)
    const dictionary savedWhat = saved.subOrEmptyDict(what);
    const dictionary nowWhat = fibersDict.subOrEmptyDict(what);
    const entry* a = savedWhat.findEntry(name, keyType::LITERAL);
    const entry* b = nowWhat.findEntry(name, keyType::LITERAL);
    return a && b && sameEntries(*a, *b);
}


void Foam::dropletFiber::warnSourcesDiffer
(
    const word& owner,
    const dictionary& saved,
    const fileName& path,
    const dictionary& fibersDict,
    const gridSettings& grid
)
{
    warnNamedDiffer
    (
        owner, path, "fixed fiber", saved.subOrEmptyDict("fixed"),
        fibersDict.subOrEmptyDict("fixed"),
        "the restart state's fibers are used (the dictionary's fixed fibers"
        " are read at a fresh start only)"
    );
    warnNamedDiffer
    (
        owner, path, "injector", saved.subOrEmptyDict("injectors"),
        fibersDict.subOrEmptyDict("injectors"),
        "the dictionary's injectors give the fibers from now on (with the"
        " count of fibers given so far from the state); the fibers already"
        " given stay as they are"
    );
    const wordList gridKeys =
        differingKeys(saved.subOrEmptyDict("grid"), gridDict(grid));
    if (!gridKeys.empty())
    {
        WarningInFunction
            << owner.c_str() << ": grid entries " << gridKeys << " differ"
            << " between the restart state " << path << " and this run's"
            << " dictionary: this run's grid is used, and the averaging"
            << " window's parcels are deposited again on it (a window of"
            << " node values keeps the old kernel's values)." << nl
            << "    Set 'restart fresh;' to start with an empty window."
            << endl;
    }
}


// ************************************************************************* //
