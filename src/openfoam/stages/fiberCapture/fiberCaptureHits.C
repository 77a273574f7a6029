/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    Discrete hits (entry collision.mode, docs/model.md sec. 3, P30-P32).
    Every segment counts the droplets it
    catches: in mode expected the expected count of eq. 9 (granted mass over
    the mean mass of a caught droplet, m_hit, from the grid's moments); in
    mode discrete a Poisson number of that mean per sample, keyed by (seed,
    fiber id, segment, sample, time index), whose mass N m_hit and momentum
    N m_hit u_droplet the segment receives instead of the expected ones.
    With depletion the parcels lose what was realised (gridBlocks::
    realiseCapture scales each parcel's part of a node's removal by q_n);
    a parcel asked more than it holds gives all it has and the hits at its
    nodes are cut by the rest (P33). Each segment also sums the expected
    mode's mass (its samples' granted masses) for the binder table.

\*---------------------------------------------------------------------------*/

#include "fiberCapture.H"
#include "PstreamReduceOps.H"
#include "collision/DiscreteHits.hpp"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dropletFiber::fiberCapture::countHits
(
    const heldFibers& held,
    couplingGrid& grid,
    const std::vector<::dropletFiber::Parcel>& parcels,
    const std::vector<::dropletFiber::DropletFieldValue>& fields,
    const std::vector<double>& granted,
    const std::vector<int>& samplesPerSegment,
    ::dropletFiber::CaptureSources& capture,
    parallelStatistics& statistics
)
{
    const bool discrete =
        collision_.mode == ::dropletFiber::CollisionMode::Discrete;
    const bool realise = discrete && depletion_;
    std::vector<double> hitMass(granted.size(), 0.0);
    ::dropletFiber::HitKey key;
    key.seed = collision_.seed;
    key.step = std::uint64_t(time_.timeIndex());
    std::size_t next = 0;
    std::size_t segment = 0;
    for (std::size_t f = 0; f < capture.size(); ++f)
    {
        key.fiberId = std::uint64_t(held.id[f]);
        const scalar fiberRadius = held.fibers[f].material().radius;
        for (std::size_t j = 0; j < capture[f].size(); ++j)
        {
            ::dropletFiber::SegmentSource& source = capture[f][j];
            key.segment = std::uint32_t(j);
            for (int s = 0; s < samplesPerSegment[segment]; ++s, ++next)
            {
                key.sample = std::uint32_t(s);
                const double mHit =
                    ::dropletFiber::hitMass
                    (
                        fields[next], fiberRadius, collision_.radiusAverage
                    );
                const ::dropletFiber::SampleHits hits =
                    ::dropletFiber::sampleHits
                    (
                        collision_.mode, granted[next], mHit, key
                    );
                source.hits += hits.count;
                // The expected mode's mass on the same fibers (P30)
                source.expectedMass += granted[next];
                hitMass[next] = hits.mass;
            }
            ++segment;
        }
    }
    std::vector<double> cut;
    bool fellShort = false;
    if (realise)
    {
        // The parcels lose what was realised instead of c_p (P31), and the
        // hits are cut where parcels could not give it (P33)
        std::vector<double> ratios(granted.size(), 0.0);
        for (std::size_t s = 0; s < granted.size(); ++s)
        {
            ratios[s] = granted[s] > 0 ? hitMass[s]/granted[s] : 0;
        }
        spreadRealised(ratios);
        capturedFraction_ =
            grid.realiseCapture
            (
                parcels, ratios, cut, fellShort, statistics,
                spreadStep_.populations ? &spreadStep_ : nullptr
            );
        spreadCut(ratios, cut);
    }
    if (discrete)
    {
        giveHits(fields, hitMass, cut, samplesPerSegment, capture);
    }
    // Every processor's cut (empty on those without samples), summed
    if (fellShort && !loggedHitsCut_)
    {
        scalar total = 0;
        for (const double c : cut)
        {
            total += c;
        }
        logHitsCutOnce(returnReduce(total, sumOp<scalar>()));
    }
}


void Foam::dropletFiber::fiberCapture::logHitsCutOnce(const scalar cut)
{
    loggedHitsCut_ = true;
    Info<< type() << " " << name() << ": at time " << time_.timeName()
        << " discrete hits asked more of some parcels than they held: they"
        << " gave all they had and the hits at their nodes were cut by "
        << cut << " kg, so that captured = removed (docs/model.md sec. 7,"
        << " P33; logged once)" << endl;
}


void Foam::dropletFiber::fiberCapture::giveHits
(
    const std::vector<::dropletFiber::DropletFieldValue>& fields,
    const std::vector<double>& hitMass,
    const std::vector<double>& cut,
    const std::vector<int>& samplesPerSegment,
    ::dropletFiber::CaptureSources& capture
) const
{
    std::size_t next = 0;
    std::size_t segment = 0;
    for (auto& fiberCapture : capture)
    {
        for (::dropletFiber::SegmentSource& source : fiberCapture)
        {
            source.mass = 0;
            source.momentum.setZero();
            for (int s = 0; s < samplesPerSegment[segment]; ++s, ++next)
            {
                const double mass =
                    cut.empty() ? hitMass[next] : max(0.0, hitMass[next] - cut[next]);
                source.mass += mass;
                source.momentum += mass*fields[next].velocity;
            }
            ++segment;
        }
    }
}


// ************************************************************************* //
