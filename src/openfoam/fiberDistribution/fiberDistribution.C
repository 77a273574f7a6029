/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "fiberDistribution.H"
#include "Pstream.H"
#include "List.H"
#include "scalarList.H"

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- Doubles per fiber in the exchange: positions and velocities (3 per
//  point), tension, captured mass and this step's capture (1 per segment)
Foam::label packedSize(const ::dropletFiber::Fiber& fiber)
{
    return Foam::label(6*fiber.pointCount() + 3*fiber.segmentCount());
}

//- Doubles of the step outcome at the end of each processor's list
constexpr Foam::label outcomeSize = 3;


//- Append a fiber's state and its capture of this step to values at k
void packFiber
(
    const ::dropletFiber::FiberState& s,
    const std::vector<::dropletFiber::SegmentSource>& capture,
    Foam::scalarList& values,
    Foam::label& k
)
{
    for (Eigen::Index i = 0; i < s.positions.size(); ++i)
    {
        values[k++] = s.positions.data()[i];
    }
    for (Eigen::Index i = 0; i < s.velocities.size(); ++i)
    {
        values[k++] = s.velocities.data()[i];
    }
    for (Eigen::Index j = 0; j < s.tension.size(); ++j)
    {
        values[k++] = s.tension(j);
    }
    for (Eigen::Index j = 0; j < s.segmentCapturedMass.size(); ++j)
    {
        values[k++] = s.segmentCapturedMass(j);
    }
    for (const auto& segment : capture)
    {
        values[k++] = segment.mass;
    }
}


//- Read a fiber's state and its capture of this step from values at k
//  (the reverse of packFiber)
void unpackFiber
(
    const Foam::scalarList& values,
    Foam::label& k,
    ::dropletFiber::FiberState& s,
    std::vector<::dropletFiber::SegmentSource>& capture
)
{
    for (Eigen::Index i = 0; i < s.positions.size(); ++i)
    {
        s.positions.data()[i] = values[k++];
    }
    for (Eigen::Index i = 0; i < s.velocities.size(); ++i)
    {
        s.velocities.data()[i] = values[k++];
    }
    for (Eigen::Index j = 0; j < s.tension.size(); ++j)
    {
        s.tension(j) = values[k++];
    }
    for (Eigen::Index j = 0; j < s.segmentCapturedMass.size(); ++j)
    {
        s.segmentCapturedMass(j) = values[k++];
    }
    for (auto& segment : capture)
    {
        segment.mass = values[k++];
    }
}


//- The fibers this processor advanced, in fiber order, then its outcome
Foam::scalarList packMine
(
    const std::vector<::dropletFiber::Fiber>& fibers,
    const ::dropletFiber::CaptureSources& capture,
    const Foam::dropletFiber::fiberDistribution::stepOutcome& local
)
{
    using Foam::dropletFiber::fiberDistribution::advancesHere;
    Foam::label size = 0;
    for (std::size_t f = 0; f < fibers.size(); ++f)
    {
        if (advancesHere(f))
        {
            size += packedSize(fibers[f]);
        }
    }
    Foam::scalarList mine(size + outcomeSize);
    Foam::label k = 0;
    for (std::size_t f = 0; f < fibers.size(); ++f)
    {
        if (advancesHere(f))
        {
            packFiber(fibers[f].state(), capture[f], mine, k);
        }
    }
    // Sub-steps as a double: exact for counts below 2^53
    mine[k++] = local.failed ? 1 : 0;
    mine[k++] = local.maxSegmentLengthError;
    mine[k++] = Foam::scalar(local.subSteps);
    return mine;
}


//- Copy into fibers and capture the fibers the other processors advanced
void unpackTheirs
(
    const Foam::List<Foam::scalarList>& perProcessor,
    std::vector<::dropletFiber::Fiber>& fibers,
    ::dropletFiber::CaptureSources& capture
)
{
    using namespace Foam;
    const std::size_t nProcs = std::size_t(Pstream::nProcs());
    std::vector<label> offset(nProcs, 0);
    for (std::size_t f = 0; f < fibers.size(); ++f)
    {
        const std::size_t owner = f % nProcs;
        if (label(owner) == Pstream::myProcNo())
        {
            continue;
        }
        const scalarList& theirs = perProcessor[label(owner)];
        label& at = offset[owner];
        if (at + packedSize(fibers[f]) + outcomeSize > theirs.size())
        {
            FatalErrorInFunction
                << "Fiber " << label(f) << ": processor " << label(owner)
                << " sent " << theirs.size() << " values, fewer than its"
                << " fibers need (the processors' fiber lists differ)."
                << abort(FatalError);
        }
        unpackFiber(theirs, at, fibers[f].mutableState(), capture[f]);
    }
}


//- The outcomes, the last values of each processor's list, combined in
//  processor order (the same on every processor)
Foam::dropletFiber::fiberDistribution::stepOutcome combinedOutcome
(
    const Foam::List<Foam::scalarList>& perProcessor
)
{
    Foam::dropletFiber::fiberDistribution::stepOutcome all;
    for (const Foam::scalarList& theirs : perProcessor)
    {
        const Foam::label at = theirs.size() - outcomeSize;
        all.failed = all.failed || theirs[at] != 0;
        all.maxSegmentLengthError =
            Foam::max(all.maxSegmentLengthError, theirs[at + 1]);
        all.subSteps += Foam::label(theirs[at + 2]);
    }
    return all;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

bool Foam::dropletFiber::fiberDistribution::advancesHere(const std::size_t f)
{
    return label(f % std::size_t(Pstream::nProcs())) == Pstream::myProcNo();
}


Foam::dropletFiber::fiberDistribution::stepOutcome
Foam::dropletFiber::fiberDistribution::exchange
(
    std::vector<::dropletFiber::Fiber>& fibers,
    ::dropletFiber::CaptureSources& capture,
    const stepOutcome& local,
    parallelStatistics& statistics
)
{
    if (!Pstream::parRun())
    {
        return local;
    }
    List<scalarList> perProcessor(Pstream::nProcs());
    perProcessor[Pstream::myProcNo()] = packMine(fibers, capture, local);

    // Exact copies (not a sum): every processor ends with the same bits
    Pstream::gatherList(perProcessor);
    Pstream::scatterList(perProcessor);
    std::vector<std::size_t> entryBytes;
    for (const scalarList& theirs : perProcessor)
    {
        entryBytes.push_back(std::size_t(theirs.byteSize()));
    }
    statistics.countGatherScatterList(entryBytes);

    unpackTheirs(perProcessor, fibers, capture);
    return combinedOutcome(perProcessor);
}

// ************************************************************************* //
