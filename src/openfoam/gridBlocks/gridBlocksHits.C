/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The exchange of the discrete hits (collision mode discrete,
    docs/model.md sec. 3 and 7, P31-P32) on the samples of the last
    grantCapture: each sample's realised over granted mass sent to the
    owners of its corners, which scale their nodes' removal r_pn by q_n
    (RealisedCapture), and the parcels' realised removal, sum_n r_pn q_n,
    added up over the blocks their deposit reached.

\*---------------------------------------------------------------------------*/

#include "gridBlocks.H"
#include "depletion/RealisedCapture.hpp"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

std::vector<double> Foam::dropletFiber::gridBlocks::realiseCapture
(
    ::dropletFiber::CaptureLimit& limit,
    const std::vector<double>& realisedOverGranted,
    parallelStatistics& statistics
)
{
    ::dropletFiber::RealisedCapture realised;
    for (std::size_t p = 0; p < grantLocal_.size(); ++p)
    {
        realised.add(grantLocal_[p], realisedOverGranted[p], limit);
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
        const List<List<scalar>> ratios =
            exchangeLists(statistics, parallelStatistics::traffic::gridQueries);
        forAll(ratios, proci)
        {
            for (std::size_t i = 0; i < grantRemote_[proci].size(); ++i)
            {
                realised.add(grantRemote_[proci][i], ratios[proci][label(i)], limit);
            }
        }
    }
    realised.scaleRemoval(limit);
    return realisedFractions(limit, statistics);
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
    for (double& f : fraction)
    {
        f = ::dropletFiber::realisedRemoval(f);
    }
    return fraction;
}

// ************************************************************************* //
