/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "levelSums.H"
#include "PstreamBuffers.H"
#include "UOPstream.H"
#include "UIPstream.H"

#include <algorithm>
#include <utility>

namespace
{

using namespace Foam;
using Foam::dropletFiber::parallelStatistics;

// Terms of a received list, (key, width values) after each other; the key
// and its giver noted where given
void addReceived
(
    const List<scalar>& in,
    const int width,
    ::dropletFiber::LevelTerms& terms,
    std::vector<std::pair<::dropletFiber::LevelKey, label>>* givers,
    const label proci
)
{
    for (label i = 0; i + width < in.size(); i += width + 1)
    {
        const auto key = ::dropletFiber::LevelKey(in[i]);
        terms.add(key, in.cdata() + i + 1);
        if (givers)
        {
            givers->emplace_back(key, proci);
        }
    }
}


// Appends a key and its values to a list
void append
(
    DynamicList<scalar>& out,
    const ::dropletFiber::LevelKey key,
    const double* values,
    const int width
)
{
    out.append(scalar(key));
    for (int c = 0; c < width; ++c)
    {
        out.append(values[c]);
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * //

Foam::List<Foam::List<Foam::scalar>> Foam::dropletFiber::exchangeLists
(
    const List<DynamicList<scalar>>& outgoing,
    PstreamBuffers& buffers,
    parallelStatistics& statistics,
    const parallelStatistics::traffic what
)
{
    buffers.clear();
    forAll(outgoing, proci)
    {
        if (!outgoing[proci].empty())
        {
            UOPstream os(proci, buffers);
            os  << static_cast<const UList<scalar>&>(outgoing[proci]);
            statistics.countSent(outgoing[proci].byteSize(), what);
        }
    }
    labelList recvSizes;
    buffers.finishedSends(recvSizes);
    List<List<scalar>> received(Pstream::nProcs());
    forAll(recvSizes, proci)
    {
        if (recvSizes[proci] > 0)
        {
            UIPstream is(proci, buffers);
            is  >> received[proci];
        }
    }
    return received;
}


::dropletFiber::LevelTable Foam::dropletFiber::sumOverProcessors
(
    const ::dropletFiber::LevelTable& local,
    const std::function<label(const ::dropletFiber::LevelKey)>& owner,
    const levelReceivers& receivers,
    parallelStatistics& statistics,
    const parallelStatistics::traffic what
)
{
    if (!Pstream::parRun())
    {
        return local;
    }
    const int width = local.width;
    List<DynamicList<scalar>> outgoing(Pstream::nProcs());
    for (std::size_t i = 0; i < local.keys.size(); ++i)
    {
        append
        (
            outgoing[owner(local.keys[i])], local.keys[i],
            local.values.data() + i*width, width
        );
    }
    // At the owners: the terms in processor order, each key's givers
    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    const List<List<scalar>> received =
        exchangeLists(outgoing, buffers, statistics, what);
    ::dropletFiber::LevelTerms terms(width);
    std::vector<std::pair<::dropletFiber::LevelKey, label>> givers;
    forAll(received, proci)
    {
        addReceived(received[proci], width, terms, &givers, proci);
    }
    const ::dropletFiber::LevelTable sums = terms.summed();
    std::stable_sort
    (
        givers.begin(), givers.end(),
        [](const auto& a, const auto& b) { return a.first < b.first; }
    );
    forAll(outgoing, proci)
    {
        outgoing[proci].clear();
    }
    std::vector<int> to;
    std::size_t g = 0;
    for (std::size_t i = 0; i < sums.keys.size(); ++i)
    {
        const ::dropletFiber::LevelKey key = sums.keys[i];
        to.clear();
        for (; g < givers.size() && givers[g].first == key; ++g)
        {
            to.push_back(int(givers[g].second));
        }
        if (receivers)
        {
            receivers(key, to);
        }
        for (const int proci : to)
        {
            append(outgoing[proci], key, sums.values.data() + i*width, width);
        }
    }
    const List<List<scalar>> answers =
        exchangeLists(outgoing, buffers, statistics, what);
    ::dropletFiber::LevelTerms whole(width);
    forAll(answers, proci)
    {
        addReceived(answers[proci], width, whole, nullptr, proci);
    }
    return whole.summed();
}


// ************************************************************************* //
