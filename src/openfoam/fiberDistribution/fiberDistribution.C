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

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

bool Foam::dropletFiber::fiberDistribution::advancesHere(const std::size_t f)
{
    return label(f % std::size_t(Pstream::nProcs())) == Pstream::myProcNo();
}


void Foam::dropletFiber::fiberDistribution::exchange
(
    std::vector<::dropletFiber::Fiber>& fibers,
    ::dropletFiber::CaptureSources& capture
)
{
    if (!Pstream::parRun())
    {
        return;
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
    mine.setSize(size);
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
        for (Eigen::Index j = 0; j < s.capturedMass.size(); ++j)
        {
            mine[k++] = s.capturedMass(j);
        }
        for (const auto& segment : capture[f])
        {
            mine[k++] = segment.mass;
        }
    }

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
        if (at + packedSize(fibers[f]) > theirs.size())
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
        for (Eigen::Index j = 0; j < s.capturedMass.size(); ++j)
        {
            s.capturedMass(j) = theirs[at++];
        }
        for (auto& segment : capture[f])
        {
            segment.mass = theirs[at++];
        }
    }
}

// ************************************************************************* //
