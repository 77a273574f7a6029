/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The exchange of the discrete hits (collision mode discrete,
    docs/model.md sec. 3 and 7, P31-P32) on the samples of the last
    grantCapture: each sample's realised over granted mass sent to the
    owners of its corners, which scale their nodes' removal r_pn by q_n
    (RealisedCapture), and the parcels' realised removal, sum_n r_pn q_n,
    added up over the blocks their deposit reached. A parcel asked more than
    it holds gives all it has, and the hits at its nodes are cut by the rest
    (P33): captured = removed.

\*---------------------------------------------------------------------------*/

#include "gridBlocks.H"
#include "depletion/RealisedCapture.hpp"
#include "PstreamReduceOps.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

std::vector<double> Foam::dropletFiber::gridBlocks::realiseCapture
(
    const std::vector<::dropletFiber::Parcel>& parcels,
    const std::vector<double>& realisedOverGranted,
    std::vector<double>& cut,
    bool& fellShort,
    parallelStatistics& statistics,
    spreadStep* spread
)
{
    ::dropletFiber::CaptureLimit& limit = limit_;
    ::dropletFiber::RealisedCapture realised;
    List<List<scalar>> ratios;
    for (std::size_t p = 0; p < grantLocal_.size(); ++p)
    {
        realised.add
        (
            grantLocal_[p], realisedOverGranted[p], limit,
            grantInterceptors_.empty() ? 1 : grantInterceptors_[p]
        );
    }
    if (Pstream::parRun())
    {
        forAll(outgoing_, proci)
        {
            outgoing_[proci].clear();
            for (const std::size_t p : grantAskedFor_[proci])
            {
                outgoing_[proci].append(realisedOverGranted[p]);
            }
        }
        // In processor order, each asker's samples in its order
        ratios =
            exchangeLists(statistics, parallelStatistics::traffic::gridQueries);
        forAll(ratios, proci)
        {
            for (std::size_t i = 0; i < grantRemote_[proci].size(); ++i)
            {
                const std::vector<double>& n = grantRemoteInterceptors_[proci];
                realised.add
                (
                    grantRemote_[proci][i], ratios[proci][label(i)], limit,
                    n.empty() ? 1 : n[i]
                );
            }
        }
    }
    if (spread)
    {
        realiseSpread(*spread, realised, statistics);
    }
    realised.scaleRemoval(limit);
    // x_p, the parcels' summed parts (their clamped terms: addShortfall)
    const std::vector<double> summedParts = realisedFractions(limit, statistics);
    std::vector<double> fraction(summedParts);
    std::vector<double> unremoved(fraction.size(), 0.0);
    fellShort = false;
    for (std::size_t p = 0; p < fraction.size(); ++p)
    {
        unremoved[p] =
            ::dropletFiber::unremovedMass
            (
                fraction[p], ::dropletFiber::parcelMass(parcels[p])
            );
        fellShort = fellShort || unremoved[p] > 0;
        fraction[p] = ::dropletFiber::realisedRemoval(fraction[p]);
    }
    cut.clear();
    reduce(fellShort, orOp<bool>());
    if (fellShort)
    {
        cut =
            cutSamples
            (
                limit, unremoved, summedParts, realisedOverGranted, ratios,
                statistics, spread
            );
    }
    return fraction;
}


std::vector<double> Foam::dropletFiber::gridBlocks::realisedFractions
(
    const ::dropletFiber::CaptureLimit& limit,
    parallelStatistics& statistics
)
{
    // This block's part for its own parcels (reached first), then the
    // copies' parts added on their processors in processor order
    const std::size_t own = reaches_.parcels.size() - copies_.size();
    const auto part = [&](const std::size_t i)
    {
        const ::dropletFiber::ParcelReach& entry = reaches_.parcels[i];
        return limit.removedFractionSum(reaches_, i, entry.saturated, entry.depth);
    };
    std::vector<::dropletFiber::FixedPointSum> sums(own);
    for (std::size_t p = 0; p < own; ++p)
    {
        sums[p] = part(p);
    }
    if (Pstream::parRun())
    {
        // The parts exact: added in any order, the same bits (serial = parallel)
        constexpr label pieces = ::dropletFiber::FixedPointSum::pieceCount;
        std::size_t next = own;
        forAll(outgoing_, proci)
        {
            outgoing_[proci].clear();
            for (std::size_t i = 0; i < copiesFrom_[proci]; ++i)
            {
                for (const double piece : part(next++).pieces())
                {
                    outgoing_[proci].append(piece);
                }
            }
        }
        const List<List<scalar>> parts =
            exchangeLists(statistics, parallelStatistics::traffic::parcels);
        forAll(parts, proci)
        {
            for (std::size_t i = 0; i < sentCopies_[proci].size(); ++i)
            {
                sums[sentCopies_[proci][i]].add
                (
                    ::dropletFiber::FixedPointSum::fromPieces
                    (
                        parts[proci].cdata() + pieces*i
                    )
                );
            }
        }
    }
    std::vector<double> fraction(own, 0.0);
    for (std::size_t p = 0; p < own; ++p)
    {
        fraction[p] = sums[p].value();
    }
    return fraction;
}


void Foam::dropletFiber::gridBlocks::addShortfalls
(
    ::dropletFiber::CaptureLimit& limit,
    const std::vector<double>& unremoved,
    const std::vector<double>& summedParts,
    parallelStatistics& statistics
)
{
    // The parcels' shortfall at this block's nodes: own parcels, then the
    // copies (in processor order, as deposited). A copy's x_p comes from its
    // parcel's processor; its unremoved mass follows from x_p and the copy's
    // own mass, the same bits as the parcel's
    const std::size_t own = reaches_.parcels.size() - copies_.size();
    std::vector<double> shortfall(unremoved);
    std::vector<double> parts(summedParts);
    shortfall.resize(reaches_.parcels.size(), 0.0);
    parts.resize(reaches_.parcels.size(), 0.0);
    if (Pstream::parRun())
    {
        forAll(outgoing_, proci)
        {
            outgoing_[proci].clear();
            for (const std::size_t p : sentCopies_[proci])
            {
                outgoing_[proci].append(summedParts[p]);
            }
        }
        const List<List<scalar>> received =
            exchangeLists(statistics, parallelStatistics::traffic::parcels);
        std::size_t next = own;
        forAll(received, proci)
        {
            for (std::size_t i = 0; i < copiesFrom_[proci]; ++i, ++next)
            {
                parts[next] = received[proci][label(i)];
                shortfall[next] =
                    ::dropletFiber::unremovedMass
                    (
                        parts[next],
                        ::dropletFiber::parcelMass(copies_[next - own])
                    );
            }
        }
    }
    for (std::size_t i = 0; i < shortfall.size(); ++i)
    {
        const ::dropletFiber::ParcelReach& entry = reaches_.parcels[i];
        if (shortfall[i] > 0)
        {
            limit.addShortfall
            (
                reaches_, i, entry.saturated, entry.depth, shortfall[i],
                parts[i]
            );
        }
    }
}


std::vector<double> Foam::dropletFiber::gridBlocks::cutSamples
(
    ::dropletFiber::CaptureLimit& limit,
    const std::vector<double>& unremoved,
    const std::vector<double>& summedParts,
    const std::vector<double>& realisedOverGranted,
    const List<List<scalar>>& remoteRatios,
    parallelStatistics& statistics,
    spreadStep* spread
)
{
    addShortfalls(limit, unremoved, summedParts, statistics);
    if (spread)
    {
        // The populations' cut on their levels (their samples read it)
        spread->cut = restrictOverBlocks(spread->demand, true, statistics);
    }
    // Each sample's cut: this block's corners, then the owners' answers
    std::vector<double> cut(grantLocal_.size(), 0.0);
    for (std::size_t p = 0; p < grantLocal_.size(); ++p)
    {
        cut[p] = realisedOverGranted[p]
           *::dropletFiber::unremovedOfSample(grantLocal_[p], limit);
    }
    if (Pstream::parRun())
    {
        forAll(outgoing_, proci)
        {
            outgoing_[proci].clear();
            for (std::size_t i = 0; i < grantRemote_[proci].size(); ++i)
            {
                outgoing_[proci].append
                (
                    remoteRatios[proci][label(i)]
                   *::dropletFiber::unremovedOfSample
                    (
                        grantRemote_[proci][i], limit
                    )
                );
            }
        }
        const List<List<scalar>> answers =
            exchangeLists(statistics, parallelStatistics::traffic::gridQueries);
        forAll(answers, proci)
        {
            for (std::size_t i = 0; i < grantAskedFor_[proci].size(); ++i)
            {
                cut[grantAskedFor_[proci][i]] += answers[proci][label(i)];
            }
        }
    }
    return cut;
}

// ************************************************************************* //
