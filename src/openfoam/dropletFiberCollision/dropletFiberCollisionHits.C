/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    Discrete hits (entry collision.mode, docs/model.md sec. 3, P30-P32) and
    the binder distribution table. Every segment counts the droplets it
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

#include "dropletFiberCollision.H"
#include "Time.H"
#include "PstreamReduceOps.H"
#include "collision/DiscreteHits.hpp"
#include "fiber/BinderDistribution.hpp"
#include "collisionSettings.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::dropletFiberCollision::countHits
(
    const std::vector<::dropletFiber::DropletFieldValue>& fields,
    const std::vector<double>& granted,
    const std::vector<int>& samplesPerSegment,
    ::dropletFiber::CaptureSources& capture
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
        key.fiberId = std::uint64_t(held_.id[f]);
        const scalar fiberRadius = held_.fibers[f].material().radius;
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
        stepCaptured_ =
            blocks_->realiseCapture
            (
                captureLimit_, stepParcels_, ratios, cut, fellShort,
                parallelStatistics_
            );
    }
    if (discrete)
    {
        giveHits(fields, hitMass, cut, samplesPerSegment, capture);
    }
    if (fellShort)
    {
        logHitsCutOnce(cut);
    }
}


void Foam::functionObjects::dropletFiberCollision::logHitsCutOnce
(
    const std::vector<double>& cut
)
{
    // Every processor's cut (empty on those without samples) is formed
    if (loggedHitsCut_)
    {
        return;
    }
    loggedHitsCut_ = true;
    scalar total = 0;
    for (const double c : cut)
    {
        total += c;
    }
    reduce(total, sumOp<scalar>());
    Info<< type() << " " << name() << ": at time " << time_.timeName()
        << " discrete hits asked more of some parcels than they held: they"
        << " gave all they had and the hits at their nodes were cut by "
        << total << " kg, so that captured = removed (docs/model.md sec. 7,"
        << " P33; logged once)" << endl;
}


void Foam::functionObjects::dropletFiberCollision::giveHits
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


void Foam::functionObjects::dropletFiberCollision::writeBinderDistribution()
{
    ::dropletFiber::BinderSums sums;
    for (const ::dropletFiber::Fiber& fiber : held_.fibers)
    {
        sums.add(fiber);
    }
    List<scalar> values(label(sums.values.size()), Zero);
    forAll(values, i)
    {
        values[i] = sums.values[std::size_t(i)];
    }
    Pstream::listCombineGather(values, plusEqOp<scalar>());
    if (!writeToFile() || !Pstream::master())
    {
        return;
    }
    forAll(values, i)
    {
        sums.values[std::size_t(i)] = values[i];
    }
    const ::dropletFiber::BinderFigures figures =
        ::dropletFiber::binderFigures(sums);
    if (!binderFile_.valid())
    {
        binderFile_ = createFile("binderDistribution");
        OFstream& os = binderFile_();
        writeHeader
        (
            os,
            "Binder along all fibers, per segment sigma = captured mass /"
            " length (docs/model.md sec. 3, discrete hits); collision mode "
          + dropletFiber::collisionModeName(collision_.mode)
          + "; expected*: the expected mode's mass on the same fibers"
        );
        writeCommented(os, "Time");
        for
        (
            const char* column :
            {
                "fiberLength", "segments", "bareFraction", "meanSigma",
                "sigmaCoV", "hitsPerLength", "expectedBareFraction",
                "expectedMeanSigma", "expectedSigmaCoV"
            }
        )
        {
            writeTabbed(os, column);
        }
        os  << endl;
    }
    OFstream& os = binderFile_();
    writeCurrentTime(os);
    os  << tab << figures.length
        << tab << label(sums.values[5])
        << tab << figures.bareFraction
        << tab << figures.meanSigma
        << tab << figures.sigmaVariation
        << tab << figures.hitsPerLength
        << tab << figures.expectedBareFraction
        << tab << figures.expectedMeanSigma
        << tab << figures.expectedSigmaVariation
        << endl;
}

// ************************************************************************* //
