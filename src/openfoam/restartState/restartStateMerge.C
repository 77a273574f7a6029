/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The processors' restart states merged into a serial run's
    (restartStateMerge.H).

\*---------------------------------------------------------------------------*/

#include "restartStateMerge.H"
#include "restartStateFiles.H"
#include "fiberStateIO.H"
#include "IFstream.H"
#include "OStringStream.H"
#include "OSspecific.H"
#include "labelList.H"
#include "scalarList.H"
#include "grid/DensityGrid.hpp"
#include "grid/DepositLog.hpp"
#include "grid/WindowTransfer.hpp"
#include <algorithm>
#include <exception>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

using namespace Foam;
using namespace Foam::dropletFiber;

//- Entries of one processor's state that a serial run's state has not, or
//  that the merge makes anew (the window's)
const wordList perProcessorEntries
(
    {
        "processors", "processor", "gridBlockProcessors", "gridBlock",
        "gridPartition", "gridWindowCounters", "gridWindowValueCount",
        "gridWindowValuesCounters"
    }
);

//- Entries merged from every processor's
const wordList mergedEntries({"fiberCount", "fibers", "depletionRemoval"});


//- An entry as text with 17 digits: equal texts, equal values
string entryText(const entry& e)
{
    OStringStream os;
    os.precision(17);
    e.write(os);
    return os.str();
}


//- The first (sub-)entry of `a` that `b` lacks or holds another value of,
//  as a dotted key; empty when they agree
word firstDifference(const dictionary& a, const dictionary& b, const word& at)
{
    for (const entry& e : a)
    {
        const word key = at.empty() ? word(e.keyword()) : word(at + "." + e.keyword());
        const entry* other = b.findEntry(e.keyword(), keyType::LITERAL);
        if (!other)
        {
            return key;
        }
        if (e.isDict() && other->isDict())
        {
            const word inner = firstDifference(e.dict(), other->dict(), key);
            if (!inner.empty())
            {
                return inner;
            }
        }
        else if (entryText(e) != entryText(*other))
        {
            return key;
        }
    }
    for (const entry& e : b)
    {
        if (!a.findEntry(e.keyword(), keyType::LITERAL))
        {
            return at.empty() ? word(e.keyword()) : word(at + "." + e.keyword());
        }
    }
    return word::null;
}


//- The value of a dotted key's entry as text, without its keyword and the
//  closing ';' ("missing" when absent)
string scopedText(const dictionary& dict, const word& key)
{
    const entry* e = dict.findScoped(key, keyType::LITERAL);
    if (!e)
    {
        return "missing";
    }
    const std::string text = entryText(*e);
    const std::size_t begin = text.find_first_not_of(" \t\n", e->keyword().size());
    const std::size_t end = text.find_last_not_of(" \t\n;");
    return begin == std::string::npos || end < begin
        ? string::null : string(text.substr(begin, end - begin + 1));
}


//- Stop unless every processor's state agrees with processor 0's on the
//  entries that are not the processors' own
void checkAgreed(const processorStates& s)
{
    dictionary common0;
    forAll(s.states, proci)
    {
        dictionary common;
        for (const entry& e : s.states[proci])
        {
            if (!perProcessorEntries.found(e.keyword()) && !mergedEntries.found(e.keyword()))
            {
                common.add(e.clone(common).ptr());
            }
        }
        if (proci == 0)
        {
            common0 = common;
            continue;
        }
        const word key = firstDifference(common0, common, word::null);
        if (!key.empty())
        {
            FatalIOErrorInFunction(s.states[proci])
                << "Restart state " << s.paths[proci] << ": entry '" << key
                << "' is " << scopedText(common, key).c_str()
                << ", in processor 0's state " << s.paths[0] << " it is "
                << scopedText(common0, key).c_str() << ": allowed is the same"
                << " value on every processor (the function object keeps it"
                << " global); the states were written by different runs or at"
                << " different times, or were edited." << exit(FatalIOError);
        }
    }
}


//- The id of fiber<id>
label fiberId(const dictionary& fibers, const word& key)
{
    label id = -1;
    if
    (
        key.size() < 6 || key.substr(0, 5) != "fiber"
     || !Foam::read(key.substr(5), id) || id < 0
    )
    {
        FatalIOErrorInFunction(fibers)
            << "Entry '" << key << "': allowed are fiber<id> with an"
            << " id >= 0 (the fiber's birth number)." << exit(FatalIOError);
    }
    return id;
}


//- The union of the processors' fibers, in id order (a serial run's)
dictionary mergedFibers(const processorStates& s)
{
    struct heldFiber { label id; label proc; const entry* state; };
    std::vector<heldFiber> held;
    forAll(s.states, proci)
    {
        const dictionary& fibers = s.states[proci].subDict("fibers");
        const label count = requiredCount(s.states[proci], "fiberCount");
        if (count != fibers.size())
        {
            FatalIOErrorInFunction(s.states[proci])
                << "Restart state " << s.paths[proci] << ": entry 'fiberCount'"
                << " is " << count << ", its dictionary 'fibers' holds "
                << fibers.size() << " fibers: the state is incomplete or was"
                << " edited." << exit(FatalIOError);
        }
        for (const entry& e : fibers)
        {
            if (!e.isDict())
            {
                FatalIOErrorInFunction(fibers)
                    << "Entry '" << e.keyword() << "': allowed is a"
                    << " dictionary (the state of one fiber)."
                    << exit(FatalIOError);
            }
            held.push_back({fiberId(fibers, e.keyword()), proci, &e});
        }
    }
    std::sort
    (
        held.begin(), held.end(),
        [](const heldFiber& a, const heldFiber& b) { return a.id < b.id; }
    );
    dictionary merged;
    for (std::size_t f = 0; f < held.size(); ++f)
    {
        if (f > 0 && held[f].id == held[f - 1].id)
        {
            FatalIOErrorInFunction(s.states[held[f].proc])
                << "Entry 'fibers.fiber" << held[f].id << "' is in "
                << s.paths[held[f - 1].proc] << " and in "
                << s.paths[held[f].proc] << ": allowed is one processor"
                << " holding each fiber (ids are birth numbers); the states"
                << " were written by different runs." << exit(FatalIOError);
        }
        merged.add(held[f].state->clone(merged).ptr());
    }
    return merged;
}


//- The processors' depletion removal lists, one after the other
dictionary mergedRemoval(const processorStates& s)
{
    DynamicList<label> origProc;
    DynamicList<label> origId;
    DynamicList<scalar> fraction;
    forAll(s.states, proci)
    {
        const dictionary& removal = s.states[proci].subDict("depletionRemoval");
        const labelList procs = removal.get<labelList>("origProc");
        const labelList ids = removal.get<labelList>("origId");
        const scalarList fractions = removal.get<scalarList>("fraction");
        if (ids.size() != procs.size() || fractions.size() != procs.size())
        {
            FatalIOErrorInFunction(removal)
                << "Entries 'origProc', 'origId' and 'fraction' of "
                << s.paths[proci] << "'s depletionRemoval have "
                << procs.size() << ", " << ids.size() << " and "
                << fractions.size() << " values: they must have as many."
                << exit(FatalIOError);
        }
        origProc.append(procs);
        origId.append(ids);
        fraction.append(fractions);
    }
    dictionary merged;
    merged.add("origProc", labelList(origProc));
    merged.add("origId", labelList(origId));
    merged.add("fraction", scalarList(fraction));
    return merged;
}


//- Stop unless every processor's state has the entry or none has
bool foundOnAll(const processorStates& s, const word& key)
{
    const bool first = s.states[0].found(key);
    forAll(s.states, proci)
    {
        if (s.states[proci].found(key) != first)
        {
            FatalIOErrorInFunction(s.states[proci])
                << "Restart state " << s.paths[proci] << " "
                << (first ? "lacks" : "has") << " the entry '" << key
                << "', processor 0's state " << s.paths[0] << " "
                << (first ? "has" : "lacks") << " it: allowed are states"
                << " of one run, all with it or all without."
                << exit(FatalIOError);
        }
    }
    return first;
}



//- The block of the grid a processor's window holds (entry gridBlock),
//  checked: six indices of a non-empty box inside the grid
::dropletFiber::IndexBox stateBlock
(
    const dictionary& state,
    const fileName& path,
    const ::dropletFiber::GridSpec& spec
)
{
    const labelList b = state.get<labelList>("gridBlock");
    ::dropletFiber::IndexBox box;
    bool inside = b.size() == 6;
    for (int d = 0; inside && d < 3; ++d)
    {
        box.lo[d] = int(b[d]);
        box.hi[d] = int(b[3 + d]);
        inside = b[d] >= 0 && b[d] <= b[3 + d] && b[3 + d] < spec.nodes[d];
    }
    if (!inside)
    {
        FatalIOErrorInFunction(state)
            << "Restart state " << path << ": entry 'gridBlock' is " << b
            << ": allowed are (lo x y z hi x y z), a block of the grid's "
            << spec.nodes[0] << " x " << spec.nodes[1] << " x "
            << spec.nodes[2] << " nodes (the case's grid settings)."
            << exit(FatalIOError);
    }
    return box;
}


//- One processor's window as node values of its block (format 2): its
//  state read and checked, a deposit log replayed on a grid of the block
::dropletFiber::WindowState blockWindowValues
(
    const dictionary& state,
    const fileName& path,
    const Foam::dropletFiber::gridSettings& grid
)
{
    const ::dropletFiber::IndexBox block = stateBlock(state, path, grid.spec);
    ::dropletFiber::WindowState window;
    window.counters = Foam::dropletFiber::windowCounters(state);
    const fileName file = path + ".gridWindow";
    window.values = Foam::dropletFiber::windowValues
    (
        file,
        Foam::dropletFiber::requiredCount(state, "gridWindowValueCount"),
        !::dropletFiber::DepositLog::holdsLog(window)
    );
    try
    {
        ::dropletFiber::DensityGrid blockGrid
        (
            grid.spec, grid.kernel, int(grid.averagingSteps),
            ::dropletFiber::GridBlock{block, block}
        );
        blockGrid.restoreWindow(window);
        return blockGrid.saveWindowPart(block);
    }
    catch (const std::exception& e)
    {
        FatalIOErrorInFunction(state)
            << "Restart state " << path << " with " << file << ": "
            << e.what() << "." << nl
            << "    The state must be read with the grid settings of the run"
            << " that wrote it (the function object's grid in"
            << " system/controlDict)." << exit(FatalIOError);
    }
    return window;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * //

Foam::dropletFiber::processorStates Foam::dropletFiber::readProcessorStates
(
    const fileName& caseDir,
    const label processors,
    const word& timeName,
    const word& name
)
{
    processorStates s;
    s.paths.setSize(processors);
    s.states.setSize(processors);
    for (label proci = 0; proci < processors; ++proci)
    {
        const fileName path =
            caseDir/("processor" + Foam::name(proci))/timeName/"uniform"
           /"dropletFiber"/name;
        s.paths[proci] = path;
        if (!isFile(path))
        {
            FatalIOErrorInFunction(path)
                << "Restart state " << path << " is missing: the case has "
                << processors << " processor directories, and a state of"
                << " function object '" << name << "' at time " << timeName
                << " is merged from all of them (each holds the fibers and"
                << " the block of the grid its processor had)." << nl
                << "    Merge a time every processor wrote, with the"
                << " processor directories as the run left them."
                << exit(FatalIOError);
        }
        IFstream is(path);
        s.states.set(proci, new dictionary(is));
        const dictionary& state = s.states[proci];
        const label count = state.lookupOrDefault<label>("processors", 0);
        const label writer = state.lookupOrDefault<label>("processor", -1);
        if (count != processors || writer != proci)
        {
            FatalIOErrorInFunction(state)
                << "Restart state " << path << ": entries 'processors' "
                << count << " and 'processor' " << writer << " (0 and -1:"
                << " absent): allowed are processors " << processors
                << " and processor " << proci << " (the case's " << processors
                << " processor directories, written by processor " << proci
                << " of a run on as many)." << nl
                << "    Merge the processor directories of one parallel run"
                << " as it wrote them; a serial run's state needs no merge."
                << exit(FatalIOError);
        }
    }
    return s;
}


Foam::dictionary Foam::dropletFiber::mergedStateDictionary
(
    const processorStates& s
)
{
    checkAgreed(s);
    const bool depletion = foundOnAll(s, "depletionRemoval");
    // Entries added are turned into tokens at the default precision: 17
    // digits keep the values as the processors wrote them
    const unsigned oldPrecision = IOstream::defaultPrecision(17);
    const dictionary fibers = mergedFibers(s);
    dictionary merged;
    for (const entry& e : s.states[0])
    {
        const word& key = e.keyword();
        if (key == "fiberCount")
        {
            merged.add("fiberCount", fibers.size());
        }
        else if (key == "fibers")
        {
            merged.add("fibers", fibers);
        }
        else if (key == "depletionRemoval" && depletion)
        {
            merged.add("depletionRemoval", mergedRemoval(s));
        }
        else if (!perProcessorEntries.found(key))
        {
            merged.add(e.clone(merged).ptr());
        }
    }
    IOstream::defaultPrecision(oldPrecision);
    return merged;
}


::dropletFiber::WindowState Foam::dropletFiber::joinedProcessorWindows
(
    const processorStates& s,
    const gridSettings& grid
)
{
    // One block's grid at a time; its node values kept for the join
    std::vector<::dropletFiber::WindowState> parts;
    parts.reserve(s.states.size());
    forAll(s.states, proci)
    {
        parts.push_back(blockWindowValues(s.states[proci], s.paths[proci], grid));
    }
    try
    {
        return ::dropletFiber::joinedWindowState
        (
            parts,
            ::dropletFiber::wholeBox(grid.spec.nodes)
        );
    }
    catch (const std::exception& e)
    {
        FatalIOErrorInFunction(s.states[0])
            << "Restart states " << s.paths[0] << " to "
            << s.paths[s.paths.size() - 1] << ": their windows (entries"
            << " gridBlock, gridWindowCounters) do not join into the whole"
            << " grid's: " << e.what() << "." << nl
            << "    Allowed are the states of one parallel run at one time,"
            << " whose blocks tile the grid." << exit(FatalIOError);
    }
    return ::dropletFiber::WindowState();
}


Foam::label Foam::dropletFiber::writeMergedRestartState
(
    const fileName& caseDir,
    const word& timeName,
    const word& name,
    const processorStates& s,
    const gridSettings& grid
)
{
    dictionary state = mergedStateDictionary(s);
    const ::dropletFiber::WindowState window = joinedProcessorWindows(s, grid);
    const unsigned oldPrecision = IOstream::defaultPrecision(17);
    state.add
    (
        "gridWindowCounters",
        toScalarList
        (
            std::vector<double>(window.counters.begin(), window.counters.end())
        )
    );
    state.add("gridWindowValueCount", label(window.values.size()));
    IOstream::defaultPrecision(oldPrecision);

    // The dictionary last, as the function object writes it: one that
    // exists belongs to a complete state. reconstructPar's copy of processor
    // 0's state goes first, with its node values for inspection (not this
    // state's)
    const fileName path = caseDir/timeName/"uniform"/"dropletFiber"/name;
    mkDir(path.path());
    rm(path);
    rm(path + ".gridWindowValues");
    writeWindowList(path + ".gridWindow", window.values);
    writeStateDictionary
    (
        path, state,
        "dropletFiber restart state of function object " + name + " at time "
      + timeName + ", merged from the states of "
      + Foam::name(s.states.size()) + " processors"
    );
    return state.subDict("fibers").size();
}

// ************************************************************************* //
