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
    const stepOutcome& local
)
{
    if (!Pstream::parRun())
    {
        return local;
    }
    const std::size_t nProcs = std::size_t(Pstream::nProcs());

    // This processor's fibers, in fiber order
    label size = 0;
    for (std::size_t f = 0; f < fibers.size(); ++f)
    {
        if (advancesHere(f))
        {
            size += packedSize(fibers[f]);
        }
    }
    List<scalarList> perProcessor(Pstream::nProcs());
    scalarList& mine = perProcessor[Pstream::myProcNo()];
    mine.setSize(size + outcomeSize);
    label k = 0;
    for (std::size_t f = 0; f < fibers.size(); ++f)
    {
        if (!advancesHere(f))
        {
            continue;
        }
        const ::dropletFiber::FiberState& s = fibers[f].state();
        for (Eigen::Index i = 0; i < s.positions.size(); ++i)
        {
            mine[k++] = s.positions.data()[i];
        }
        for (Eigen::Index i = 0; i < s.velocities.size(); ++i)
        {
            mine[k++] = s.velocities.data()[i];
        }
        for (Eigen::Index j = 0; j < s.tension.size(); ++j)
        {
            mine[k++] = s.tension(j);
        }
        for (Eigen::Index j = 0; j < s.segmentCapturedMass.size(); ++j)
        {
            mine[k++] = s.segmentCapturedMass(j);
        }
        for (const auto& segment : capture[f])
        {
            mine[k++] = segment.mass;
        }
    }
    // Sub-steps as a double: exact for counts below 2^53
    mine[k++] = local.failed ? 1 : 0;
    mine[k++] = local.maxSegmentLengthError;
    mine[k++] = scalar(local.subSteps);

    // Exact copies (not a sum): every processor ends with the same bits
    Pstream::gatherList(perProcessor);
    Pstream::scatterList(perProcessor);

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
        ::dropletFiber::FiberState& s = fibers[f].mutableState();
        for (Eigen::Index i = 0; i < s.positions.size(); ++i)
        {
            s.positions.data()[i] = theirs[at++];
        }
        for (Eigen::Index i = 0; i < s.velocities.size(); ++i)
        {
            s.velocities.data()[i] = theirs[at++];
        }
        for (Eigen::Index j = 0; j < s.tension.size(); ++j)
        {
            s.tension(j) = theirs[at++];
        }
        for (Eigen::Index j = 0; j < s.segmentCapturedMass.size(); ++j)
        {
            s.segmentCapturedMass(j) = theirs[at++];
        }
        for (auto& segment : capture[f])
        {
            segment.mass = theirs[at++];
        }
    }

    // The outcomes, the last values of each processor's list, combined in
    // processor order (the same on every processor)
    stepOutcome all;
    for (const scalarList& theirs : perProcessor)
    {
        const label at = theirs.size() - outcomeSize;
        all.failed = all.failed || theirs[at] != 0;
        all.maxSegmentLengthError =
            max(all.maxSegmentLengthError, theirs[at + 1]);
        all.subSteps += label(theirs[at + 2]);
    }
    return all;
}

// ************************************************************************* //
