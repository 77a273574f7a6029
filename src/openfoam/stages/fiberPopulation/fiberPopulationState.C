/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The fibers' part of the restart state: the run's continuous time, every
    fiber held here (fiber<id>: its state and origin, at full precision),
    the injectors' counts and the fibers' totals; read back with every value
    checked.

\*---------------------------------------------------------------------------*/

#include "fiberPopulation.H"
#include "dictionaryChecks.H"
#include "fiberStateIO.H"
#include "restartSources.H"
#include "restartStateFiles.H"
#include "PstreamReduceOps.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::dropletFiber::fiberPopulation::nextFiberIdAfterRestart() const
{
    // The ids are birth numbers: the fixed fibers of the dictionary first,
    // then every fiber injected (the injectors' counts), as in the run that
    // wrote the state; above every id held, should the dictionary differ
    label born =
        label(readFixedFibers(sources_).size());
    for (const auto& injector : injectors_)
    {
        born += label(injector.injectedCount());
    }
    label above = 0;
    for (const label id : held_.id)
    {
        above = max(above, id + 1);
    }
    return max(born, returnReduce(above, maxOp<label>()));
}


void Foam::dropletFiber::fiberPopulation::restoreFibers
(
    const dictionary& state,
    const fileName& path
)
{
    const dictionary& fibers = state.subDict("fibers");
    held_ = heldFibers();
    for (const entry& e : fibers)
    {
        const dictionary& d = requiredSubDict
        (
            fibers, e.keyword(), "the state of one fiber"
        );
        // fiber<id>: the id, a birth number
        label id = -1;
        const word& key = e.keyword();
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
        ::dropletFiber::FiberState s = fiberStateFromDict(d);
        checkedCoreCall
        (
            d, [&]() { held_.fibers.emplace_back(std::move(s)); }
        );
        held_.origin.push_back(d.get<word>("origin"));
        held_.id.push_back(id);
    }
    // States of earlier versions have no count
    const label count = state.lookupOrDefault<label>("fiberCount", -1);
    if (count >= 0 && count != label(held_.size()))
    {
        FatalIOErrorInFunction(state)
            << "Restart state " << path << ": entry 'fiberCount' is " << count
            << ", its dictionary 'fibers' holds " << label(held_.size())
            << " fibers: the state is incomplete or was edited." << nl
            << "    Restart from an earlier time, or set 'restart fresh;'."
            << exit(FatalIOError);
    }
}


void Foam::dropletFiber::fiberPopulation::restoreInjectorCounts
(
    const dictionary& injectors,
    const dictionary& sources
)
{
    // An injector new to this run has injected none yet; none has injected
    // more than its rate gives by the state's time, where the state says
    // that the rate was the dictionary's (an injector edited since is
    // warned about: warnSourcesDiffer)
    for (auto& injector : injectors_)
    {
        const word key(injector.spec().name);
        const label count =
            getLabelInRange(injectors, key, 0, 0, labelMax);
        const bool edited =
            !sources.empty()
         && !sameSource
            (
                sources, sources_, "injectors", key
            );
        if (edited)
        {
            injector.setInjectedCount(count);
            continue;
        }
        const label born = checkedCoreCall
        (
            injectors,
            [&]() { return label(injector.bornBy(clock_)); }
        );
        if (count > born)
        {
            const auto& spec = injector.spec();
            FatalIOErrorInFunction(injectors)
                << "Entry '" << key << "' is " << count << ": injector '"
                << key << "' (rate " << spec.rate << ", startTime "
                << spec.startTime << ", endTime " << spec.endTime << ") has"
                << " given at most " << born << " fibers by time "
                << time_.timeName() << "." << nl
                << "    Restart from a state its run wrote, or set 'restart"
                << " fresh;'." << exit(FatalIOError);
        }
        injector.setInjectedCount(count);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dropletFiber::fiberPopulation::writeState
(
    const fileName&,
    dictionary& state,
    dictionary& totals
)
{
    state.add("time", clockIndex_ == time_.timeIndex() ? clock_ : time_.value());
    state.add("timeIndex", time_.timeIndex());
    // The count of the fibers written here: a restart checks the state's
    // fibers against it
    state.add("fiberCount", label(held_.size()));
    dictionary fibers;
    for (std::size_t f = 0; f < held_.size(); ++f)
    {
        dictionary d = fiberStateDict(held_.fibers[f].state());
        d.add("origin", held_.origin[f]);
        fibers.add(word("fiber" + Foam::name(held_.id[f])), d);
    }
    state.add("fibers", fibers);

    dictionary injectors;
    for (const auto& injector : injectors_)
    {
        injectors.add(word(injector.spec().name), label(injector.injectedCount()));
    }
    state.add("injectors", injectors);

    totals.add("fiberMassAdded", totals_.massAdded);
    totals.add("fiberMassRemoved", totals_.massRemoved);
    totals.add("fibersRemoved", totals_.removed);
    if (totals_.countBinderRemoved)
    {
        totals.add("fiberBinderRemoved", totals_.binderRemoved);
        totals.add("fibersLaid", totals_.laid);
        totals.add("fiberGlassLaid", totals_.glassLaid);
        totals.add("fiberBinderLaid", totals_.binderLaid);
    }
}


void Foam::dropletFiber::fiberPopulation::readState
(
    const dictionary& state,
    const fileName& path
)
{
    // The state's time and index were checked against the run's
    // (couplingRestart)
    clock_ = state.get<scalar>("time");
    clockIndex_ = state.get<label>("timeIndex");
    restoreFibers(state, path);
    restoreInjectorCounts
    (
        state.subDict("injectors"), state.subOrEmptyDict("sources")
    );
    const dictionary& totals = state.subDict("totals");
    const auto nonNegative = [&totals](const word& key)
    {
        return getCheckedScalar
        (
            totals, key, nullptr, [](scalar v) { return v >= 0; }, ">= 0"
        );
    };
    totals_.massAdded = nonNegative("fiberMassAdded");
    totals_.massRemoved = nonNegative("fiberMassRemoved");
    totals_.removed = requiredCount(totals, "fibersRemoved");
    // States written without a belt have none: the binder lost before is
    // then unknown and taken as 0 (the binder balance says so)
    totals_.binderRemoved =
        totals.found("fiberBinderRemoved") ? nonNegative("fiberBinderRemoved") : 0;
    restoreLaidTotals(state, totals, path);
}


void Foam::dropletFiber::fiberPopulation::restoreLaidTotals
(
    const dictionary& state,
    const dictionary& totals,
    const fileName& path
)
{
    const auto nonNegative = [](const dictionary& d, const word& key)
    {
        return getCheckedScalar
        (
            d, key, nullptr, [](scalar v) { return v >= 0; }, ">= 0"
        );
    };
    if (totals.found("fibersLaid"))
    {
        totals_.laid = requiredCount(totals, "fibersLaid");
        totals_.glassLaid = nonNegative(totals, "fiberGlassLaid");
        totals_.binderLaid = nonNegative(totals, "fiberBinderLaid");
        return;
    }
    // A state written before the population counted the fibers the belt
    // took has them only in the mat's totals: the same sums
    const dictionary* mat = state.findDict("laydown");
    if (mat)
    {
        totals_.laid = requiredCount(*mat, "computed");
        totals_.glassLaid = nonNegative(*mat, "glass");
        totals_.binderLaid = nonNegative(*mat, "binder");
        Info<< type() << " " << name() << ": the restart state " << path
            << " has the fibers laid in the mat's totals only: taken from"
            << " there" << nl;
    }
}


// ************************************************************************* //
