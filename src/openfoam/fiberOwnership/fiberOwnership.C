/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "fiberOwnership.H"
#include "PstreamBuffers.H"
#include "UIPstream.H"
#include "UOPstream.H"
#include "PstreamReduceOps.H"
#include "scalarList.H"
#include "wordList.H"

#include <algorithm>
#include <numeric>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- What the fibers' exchanges are counted as
constexpr auto fiberTraffic =
    Foam::dropletFiber::parallelStatistics::traffic::fibers;


using namespace Foam;

template<class EigenType>
void append(const EigenType& m, DynamicList<scalar>& values)
{
    for (Eigen::Index i = 0; i < m.size(); ++i)
    {
        values.append(m.data()[i]);
    }
}


template<class EigenType>
void extract(const scalarList& values, label& k, EigenType& m)
{
    for (Eigen::Index i = 0; i < m.size(); ++i)
    {
        m.data()[i] = values[k++];
    }
}


void appendEnd(const ::dropletFiber::EndCondition& e, DynamicList<scalar>& values)
{
    values.append(scalar(int(e.type)));
    append(e.anchorVelocity, values);
    append(e.clampDirection, values);
}


void extractEnd(const scalarList& values, label& k, ::dropletFiber::EndCondition& e)
{
    e.type = ::dropletFiber::EndType(int(values[k++]));
    extract(values, k, e.anchorVelocity);
    extract(values, k, e.clampDirection);
}


//- A fiber's whole state as values, exact (the point count first)
scalarList packState(const ::dropletFiber::FiberState& s)
{
    DynamicList<scalar> values;
    values.append(scalar(s.positions.cols()));
    append(s.positions, values);
    append(s.velocities, values);
    append(s.restLengths, values);
    append(s.segmentCapturedMass, values);
    append(s.tension, values);
    append(s.externalForce, values);
    values.append(s.material.radius);
    values.append(s.material.density);
    values.append(s.material.youngsModulus);
    appendEnd(s.startEnd, values);
    appendEnd(s.endEnd, values);
    values.append(s.immobile ? 1 : 0);
    values.append(s.represents);
    values.append(s.populationSpread);
    // The turbulent fluctuation travels with its fiber (0 or n columns)
    values.append(scalar(s.turbulentVelocity.cols()));
    append(s.turbulentVelocity, values);
    append(s.segmentHits, values);
    append(s.segmentExpectedMass, values);
    return scalarList(std::move(values));
}


//- The reverse of packState
::dropletFiber::FiberState unpackState(const scalarList& values)
{
    label k = 0;
    const Eigen::Index n = Eigen::Index(values[k++]);
    ::dropletFiber::FiberState s;
    s.positions.resize(3, n);
    s.velocities.resize(3, n);
    s.restLengths.resize(n - 1);
    s.segmentCapturedMass.resize(n - 1);
    s.tension.resize(n - 1);
    s.externalForce.resize(3, n);
    extract(values, k, s.positions);
    extract(values, k, s.velocities);
    extract(values, k, s.restLengths);
    extract(values, k, s.segmentCapturedMass);
    extract(values, k, s.tension);
    extract(values, k, s.externalForce);
    s.material.radius = values[k++];
    s.material.density = values[k++];
    s.material.youngsModulus = values[k++];
    extractEnd(values, k, s.startEnd);
    extractEnd(values, k, s.endEnd);
    s.immobile = values[k++] != 0;
    s.represents = values[k++];
    s.populationSpread = values[k++];
    s.turbulentVelocity.resize(3, Eigen::Index(values[k++]));
    extract(values, k, s.turbulentVelocity);
    s.segmentHits.resize(n - 1);
    extract(values, k, s.segmentHits);
    s.segmentExpectedMass.resize(n - 1);
    extract(values, k, s.segmentExpectedMass);
    return s;
}


point firstPoint(const ::dropletFiber::Fiber& fiber)
{
    const Eigen::Matrix3Xd& x = fiber.positions();
    return point(x(0, 0), x(1, 0), x(2, 0));
}


//- The held fibers whose first point left this processor's cells, per
//  processor to ask: their places in held and their first points
void fibersToAsk
(
    const Foam::dropletFiber::processorBoxes& boxes,
    const Foam::dropletFiber::heldFibers& held,
    List<DynamicList<label>>& fiberOf,
    List<DynamicList<point>>& pointOf
)
{
    for (std::size_t k = 0; k < held.size(); ++k)
    {
        const ::dropletFiber::Fiber& fiber = held.fibers[k];
        const point p = firstPoint(fiber);
        if (fiber.immobile() || boxes.holds(p))
        {
            continue;
        }
        for (const label proci : boxes.candidates(p))
        {
            fiberOf[proci].append(label(k));
            pointOf[proci].append(p);
        }
    }
}


//- Exchange 1 and 2: the points to the processors asked, which answer
//  whether their cells hold them. Returns per held fiber its new holder
//  (-1: stays here), the lowest processor that holds its first point.
labelList newHolders
(
    const Foam::dropletFiber::processorBoxes& boxes,
    const std::size_t nHeld,
    const List<DynamicList<label>>& fiberOf,
    const List<DynamicList<point>>& pointOf,
    Foam::dropletFiber::parallelStatistics& statistics
)
{
    PstreamBuffers questions(Pstream::commsTypes::nonBlocking);
    const labelList recvSizes = askProcessors(pointOf, questions, statistics);

    PstreamBuffers answers(Pstream::commsTypes::nonBlocking);
    forAll(recvSizes, proci)
    {
        if (recvSizes[proci])
        {
            UIPstream is(proci, questions);
            const List<point> points(is);
            labelList held(points.size(), 0);
            forAll(points, i)
            {
                held[i] = boxes.holds(points[i]) ? 1 : 0;
            }
            UOPstream os(proci, answers);
            os << held;
            statistics.countSent
            (
                held.byteSize(), fiberTraffic
            );
        }
    }
    answers.finishedSends();

    // Processors in increasing order: the first that holds it is the lowest
    labelList holder(label(nHeld), -1);
    forAll(pointOf, proci)
    {
        if (pointOf[proci].size())
        {
            UIPstream is(proci, answers);
            const labelList held(is);
            forAll(held, i)
            {
                label& h = holder[fiberOf[proci][i]];
                if (held[i] && h < 0)
                {
                    h = proci;
                }
            }
        }
    }
    return holder;
}


//- Exchange 3: the fibers to their new holders, received ones appended
void sendFibers
(
    const labelList& holder,
    Foam::dropletFiber::heldFibers& held,
    Foam::dropletFiber::parallelStatistics& statistics
)
{
    PstreamBuffers parcelsOfFibers(Pstream::commsTypes::nonBlocking);
    List<DynamicList<label>> leaving(Pstream::nProcs());
    forAll(holder, k)
    {
        if (holder[k] >= 0)
        {
            leaving[holder[k]].append(k);
        }
    }
    forAll(leaving, proci)
    {
        if (leaving[proci].empty())
        {
            continue;
        }
        labelList ids;
        wordList origins;
        List<scalarList> states;
        for (const label k : leaving[proci])
        {
            ids.append(held.id[k]);
            origins.append(held.origin[k]);
            states.append(packState(held.fibers[k].state()));
            statistics.countSent
            (
                states.last().byteSize() + origins.last().size(),
                fiberTraffic
            );
        }
        statistics.countSent
        (
            ids.byteSize(), fiberTraffic
        );
        UOPstream os(proci, parcelsOfFibers);
        os << ids << origins << states;
    }
    labelList recvSizes;
    parcelsOfFibers.finishedSends(recvSizes);

    held.keepIf([&holder](std::size_t k) { return holder[label(k)] < 0; });
    forAll(recvSizes, proci)
    {
        if (recvSizes[proci])
        {
            UIPstream is(proci, parcelsOfFibers);
            const labelList ids(is);
            const wordList origins(is);
            const List<scalarList> states(is);
            forAll(ids, i)
            {
                held.fibers.emplace_back(unpackState(states[i]));
                held.origin.push_back(origins[i]);
                held.id.push_back(ids[i]);
            }
        }
    }
}


//- Sort the held fibers by id again (after fibers arrived)
void sortById(Foam::dropletFiber::heldFibers& held)
{
    std::vector<std::size_t> order(held.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::sort
    (
        order.begin(), order.end(),
        [&held](std::size_t a, std::size_t b) { return held.id[a] < held.id[b]; }
    );
    Foam::dropletFiber::heldFibers sorted;
    sorted.weighted = held.weighted;
    for (const std::size_t k : order)
    {
        sorted.fibers.push_back(std::move(held.fibers[k]));
        sorted.origin.push_back(held.origin[k]);
        sorted.id.push_back(held.id[k]);
    }
    held = std::move(sorted);
}


//- passOn by holderRule::roundRobin: each fiber to its birth number's
//  processor (collective); the fibers sent
label passOnByBirth
(
    Foam::dropletFiber::heldFibers& held,
    Foam::dropletFiber::parallelStatistics& statistics
)
{
    labelList holder(label(held.size()), -1);
    label sent = 0;
    forAll(holder, k)
    {
        const label proci = held.id[k] % Pstream::nProcs();
        if (proci != Pstream::myProcNo())
        {
            holder[k] = proci;
            ++sent;
        }
    }
    if (!returnReduce(sent > 0, orOp<bool>()))
    {
        return 0;
    }
    sendFibers(holder, held, statistics);
    sortById(held);
    return sent;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dropletFiber::heldFibers::append
(
    ::dropletFiber::Fiber&& fiber,
    const word& from,
    const label fiberId
)
{
    fibers.push_back(std::move(fiber));
    origin.push_back(from);
    id.push_back(fiberId);
}


// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

const Foam::wordList& Foam::dropletFiber::fiberOwnership::holderRuleNames()
{
    static const wordList names{"cells", "roundRobin"};
    return names;
}


Foam::dropletFiber::fiberOwnership::holderRule
Foam::dropletFiber::fiberOwnership::holderRuleFromName(const word& name)
{
    // The entry is checked against holderRuleNames() when read
    return name == "roundRobin" ? holderRule::roundRobin : holderRule::cells;
}


void Foam::dropletFiber::fiberOwnership::keepBornHere
(
    const processorBoxes& boxes,
    heldFibers& held,
    parallelStatistics& statistics,
    const holderRule rule
)
{
    if (!Pstream::parRun() || held.size() == 0)
    {
        return;
    }
    if (rule == holderRule::roundRobin)
    {
        held.keepIf
        (
            [&held](std::size_t k)
            {
                return held.id[k] % Pstream::nProcs() == Pstream::myProcNo();
            }
        );
        return;
    }
    List<point> first(label(held.size()));
    forAll(first, k)
    {
        first[k] = firstPoint(held.fibers[k]);
    }
    const labelList holder = boxes.lowestHolders(first, Pstream::masterNo());
    statistics.countCombineGatherScatter
    (
        holder.byteSize(), fiberTraffic
    );
    held.keepIf
    (
        [&holder](std::size_t k)
        {
            return holder[label(k)] == Pstream::myProcNo();
        }
    );
}


Foam::label Foam::dropletFiber::fiberOwnership::passOn
(
    const processorBoxes& boxes,
    heldFibers& held,
    parallelStatistics& statistics,
    const holderRule rule
)
{
    if (!Pstream::parRun())
    {
        return 0;
    }
    if (rule == holderRule::roundRobin)
    {
        return passOnByBirth(held, statistics);
    }
    List<DynamicList<label>> fiberOf(Pstream::nProcs());
    List<DynamicList<point>> pointOf(Pstream::nProcs());
    fibersToAsk(boxes, held, fiberOf, pointOf);
    bool asking = false;
    for (const DynamicList<label>& fibers : fiberOf)
    {
        asking = asking || fibers.size();
    }
    if (!returnReduce(asking, orOp<bool>()))
    {
        return 0;
    }
    const labelList holder =
        newHolders(boxes, held.size(), fiberOf, pointOf, statistics);
    label sent = 0;
    for (const label proci : holder)
    {
        sent += proci >= 0 ? 1 : 0;
    }
    sendFibers(holder, held, statistics);
    sortById(held);
    return sent;
}

// ************************************************************************* //
