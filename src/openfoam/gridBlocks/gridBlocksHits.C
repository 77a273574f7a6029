/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The exchange of the discrete hits (collision mode discrete,
    docs/model.md sec. 3 and 7, P31-P32) on the samples of the last
    grantCapture: each sample's realised over granted mass sent to the
    owners of its corners, which scale their taken fractions by q_n
    (RealisedCapture).

\*---------------------------------------------------------------------------*/

#include "gridBlocks.H"
#include "depletion/RealisedCapture.hpp"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dropletFiber::gridBlocks::realiseCapture
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
}

// ************************************************************************* //
