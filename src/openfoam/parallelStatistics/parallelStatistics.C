/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "parallelStatistics.H"
#include "Pstream.H"
#include "List.H"
#include "ops.H"

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- The schedule of Pstream's gathers and scatters on the world
//  communicator (every processor's place: what is sent to a neighbour below
//  depends on the neighbour's place)
const Foam::List<Foam::UPstream::commsStruct>& allComms()
{
    using Foam::UPstream;
    return
        UPstream::nProcs() < UPstream::nProcsSimpleSum
      ? UPstream::linearCommunication()
      : UPstream::treeCommunication();
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dropletFiber::parallelStatistics::startStep()
{
    step_.bytesSent = 0;
    step_.bytesParcels = 0;
    step_.bytesGridQueries = 0;
    step_.bytesFibers = 0;
}


void Foam::dropletFiber::parallelStatistics::holding
(
    const std::size_t nodes,
    const std::size_t fibers
)
{
    step_.nodesHeld = scalar(nodes);
    step_.fibersHeld = scalar(fibers);
}


void Foam::dropletFiber::parallelStatistics::countCombineGatherScatter
(
    const std::size_t listBytes,
    const traffic what
)
{
    if (!Pstream::parRun())
    {
        return;
    }
    // The gather sends the combined list up once, the scatter down to each
    // neighbour below
    const UPstream::commsStruct& my = allComms()[Pstream::myProcNo()];
    const std::size_t messages =
        (my.above() >= 0 ? 1 : 0) + std::size_t(my.below().size());
    countSent(messages*listBytes, what);
}


void Foam::dropletFiber::parallelStatistics::countSent
(
    const std::size_t bytes,
    const traffic what
)
{
    step_.bytesSent += scalar(bytes);
    switch (what)
    {
        case traffic::parcels:
            step_.bytesParcels += scalar(bytes);
            break;
        case traffic::gridQueries:
            step_.bytesGridQueries += scalar(bytes);
            break;
        case traffic::fibers:
            step_.bytesFibers += scalar(bytes);
            break;
    }
}


Foam::dropletFiber::parallelStatistics::figures
Foam::dropletFiber::parallelStatistics::maxOverProcessors() const
{
    // One gather to the master, which writes them (counts are exact in a
    // double)
    List<scalar> values(6);
    values[0] = step_.nodesHeld;
    values[1] = step_.fibersHeld;
    values[2] = step_.bytesSent;
    values[3] = step_.bytesParcels;
    values[4] = step_.bytesGridQueries;
    values[5] = step_.bytesFibers;
    Pstream::listCombineGather(values, maxEqOp<scalar>());
    figures maxima;
    maxima.nodesHeld = values[0];
    maxima.fibersHeld = values[1];
    maxima.bytesSent = values[2];
    maxima.bytesParcels = values[3];
    maxima.bytesGridQueries = values[4];
    maxima.bytesFibers = values[5];
    return maxima;
}

// ************************************************************************* //
