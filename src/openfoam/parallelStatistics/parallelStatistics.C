/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "parallelStatistics.H"
#include "Pstream.H"
#include "List.H"
#include "ops.H"

#include <cmath>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- The schedule of Pstream's gathers and scatters on the world
//  communicator (every processor's place: what is sent to a neighbour below
//  depends on the neighbour's place)
#if OPENFOAM >= 2506
// v2506: the schedules are UPstream::commsStructList, and linearCommunication()
// and treeCommunication() take the communicator (no default)
const Foam::UPstream::commsStructList& allComms()
{
    using Foam::UPstream;
    return
        UPstream::nProcs() < UPstream::nProcsSimpleSum
      ? UPstream::linearCommunication(UPstream::worldComm)
      : UPstream::treeCommunication(UPstream::worldComm);
}
#else
const Foam::List<Foam::UPstream::commsStruct>& allComms()
{
    using Foam::UPstream;
    return
        UPstream::nProcs() < UPstream::nProcsSimpleSum
      ? UPstream::linearCommunication()
      : UPstream::treeCommunication();
}
#endif

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar& Foam::dropletFiber::parallelStatistics::work::operator[]
(
    const label i
)
{
    scalar* const figure[size] =
    {
        &parcels, &parcelCopies, &nodeWeights, &collisionSamples,
        &fiberPoints, &cpuDeposit, &cpuCollision, &cpuFibers
    };
    return *figure[i];
}


Foam::scalar Foam::dropletFiber::parallelStatistics::work::operator[]
(
    const label i
) const
{
    return const_cast<work&>(*this)[i];
}


void Foam::dropletFiber::parallelStatistics::startStep()
{
    work_ = work();
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


void Foam::dropletFiber::parallelStatistics::countDeposit
(
    const scalar parcels,
    const scalar parcelCopies,
    const scalar nodeWeights
)
{
    work_.parcels += parcels;
    work_.parcelCopies += parcelCopies;
    work_.nodeWeights += nodeWeights;
}


void Foam::dropletFiber::parallelStatistics::countCollisionSamples
(
    const std::size_t samples
)
{
    work_.collisionSamples += scalar(samples);
}


void Foam::dropletFiber::parallelStatistics::countFiberPoints
(
    const std::size_t points
)
{
    work_.fiberPoints += scalar(points);
}


void Foam::dropletFiber::parallelStatistics::addCpuTime
(
    const stage s,
    const scalar seconds
)
{
    switch (s)
    {
        case stage::deposit:
            work_.cpuDeposit += seconds;
            break;
        case stage::collision:
            work_.cpuCollision += seconds;
            break;
        case stage::fibers:
            work_.cpuFibers += seconds;
            break;
    }
}


Foam::dropletFiber::parallelStatistics::spread
Foam::dropletFiber::parallelStatistics::overProcessors()
{
    // Two gathers to the master, which writes them (counts are exact in a
    // double): the maxima of everything, the sums of the work
    const label nHeld = 6;
    List<scalar> maxima(nHeld + work::size);
    List<scalar> sums(work::size);
    maxima[0] = step_.nodesHeld;
    maxima[1] = step_.fibersHeld;
    maxima[2] = step_.bytesSent;
    maxima[3] = step_.bytesParcels;
    maxima[4] = step_.bytesGridQueries;
    maxima[5] = step_.bytesFibers;
    for (label i = 0; i < work::size; ++i)
    {
        maxima[nHeld + i] = work_[i];
        sums[i] = work_[i];
    }
    Pstream::listCombineGather(maxima, maxEqOp<scalar>());
    Pstream::listCombineGather(sums, plusEqOp<scalar>());
    spread all;
    all.maxima.nodesHeld = maxima[0];
    all.maxima.fibersHeld = maxima[1];
    all.maxima.bytesSent = maxima[2];
    all.maxima.bytesParcels = maxima[3];
    all.maxima.bytesGridQueries = maxima[4];
    all.maxima.bytesFibers = maxima[5];
    for (label i = 0; i < work::size; ++i)
    {
        all.maxWork[i] = maxima[nHeld + i];
        all.meanWork[i] = sums[i]/Pstream::nProcs();
        periodMax_[i] += all.maxWork[i];
        periodMean_[i] += all.meanWork[i];
    }
    ++periodSteps_;
    return all;
}


void Foam::dropletFiber::parallelStatistics::reportBalance
(
    Ostream& os,
    const std::string& who,
    const word& timeName
)
{
    // max / mean of the sums over the period: the steps weighted by their
    // work, a processor idle in every step counted as such
    auto ratio = [this](const label i)
    {
        // Two decimals: the spread of a timing, not a result
        const scalar r =
            periodMean_[i] > 0 ? periodMax_[i]/periodMean_[i] : 1.0;
        return std::round(100*r)/100;
    };
    if (Pstream::parRun() && periodSteps_ > 0)
    {
        os  << who.c_str() << " work balance over " << Pstream::nProcs()
            << " processors, " << periodSteps_ << " steps to time "
            << timeName << " (max / mean over processors; 1 is even):" << nl
            << "    thread CPU time: deposit " << ratio(5)
            << ", collision " << ratio(6) << ", fiber step " << ratio(7) << nl
            << "    work: parcels " << ratio(0) << ", parcel copies "
            << ratio(1) << ", node weights " << ratio(2)
            << ", collision samples " << ratio(3) << ", fiber points "
            << ratio(4) << nl;
    }
    periodMax_ = work();
    periodMean_ = work();
    periodSteps_ = 0;
}

// ************************************************************************* //
