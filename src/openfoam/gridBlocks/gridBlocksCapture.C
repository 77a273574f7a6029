/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    Depletion over the grid's blocks (docs/model.md sec. 7, P12-P14, P19):
    each sample's demand attributed by the owners of its corners to their
    nodes (grantCapture), the nodes' grants, and each parcel's captured
    fraction from the optical depths of the nodes its deposit reached, added
    up over the blocks it reached (removeCaptured).

\*---------------------------------------------------------------------------*/

#include "gridBlocks.H"
#include "UOPstream.H"
#include "UIPstream.H"
#include "grid/MultilinearWeights.hpp"

#include <stdexcept>
#include <string>
#include <algorithm>
#include <unordered_map>

namespace
{
// A request for a sample's demand: its point, m_s / Sigma and its strip across
// the flow (P21: each owner forms its own corners' self-shadow from them); with
// weighted fibers one value more, the physical fibers behind it (P40)
constexpr Foam::label requestSize = 7;
}

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dropletFiber::gridBlocks::attributeDemand
(
    const ::dropletFiber::DensityGrid& grid,
    const std::vector<Eigen::Vector3d>& points,
    const std::vector<double>& massShares,
    const std::vector<Eigen::Vector3d>& strips,
    ::dropletFiber::CaptureLimit& limit,
    std::vector<::dropletFiber::SampleCapture>& local,
    std::vector<std::vector<std::size_t>>& askedFor
)
{
    local.assign(points.size(), ::dropletFiber::SampleCapture());
    for (std::size_t p = 0; p < points.size(); ++p)
    {
        if (!(massShares[p] > 0))
        {
            continue; // no capture: nothing asked of any node
        }
        const ::dropletFiber::CornerWeights corners =
            ::dropletFiber::multilinearWeights(spec_, points[p]);
        local[p] =
            ::dropletFiber::attributeOwnedCorners
            (
                grid, corners, massShares[p], Eigen::Vector3d::Zero(),
                strips[p]
            );
        const scalar interceptors =
            grantInterceptors_.empty() ? 1 : grantInterceptors_[p];
        limit.addDemand(local[p], interceptors);
        if (Pstream::parRun())
        {
            const scalar extra[requestSize - 3 + 1] =
            {
                massShares[p], strips[p].x(), strips[p].y(), strips[p].z(),
                interceptors
            };
            askCornerOwners
            (
                corners, points[p], p, askedFor, extra, grantRequestSize_ - 3
            );
        }
    }
}


std::vector<double> Foam::dropletFiber::gridBlocks::grantCapture
(
    ::dropletFiber::DensityGrid& grid,
    const std::vector<Eigen::Vector3d>& points,
    const std::vector<double>& massShares,
    const std::vector<double>* interceptors,
    const std::vector<Eigen::Vector3d>& strips,
    const std::vector<::dropletFiber::Parcel>& parcels,
    const double dt,
    ::dropletFiber::CaptureLimitReport& report,
    std::vector<double>& captured,
    parallelStatistics& statistics,
    spreadStep* spread
)
{
    const auto what = parallelStatistics::traffic::gridQueries;
    ::dropletFiber::CaptureLimit& limit = limit_;
    limit.clear();
    // Weighted fibers: each request carries its physical fibers too
    grantInterceptors_.clear();
    if (interceptors)
    {
        grantInterceptors_ = *interceptors;
    }
    grantRequestSize_ = interceptors ? requestSize + 1 : requestSize;
    grantRemoteInterceptors_.assign(outgoing_.size(), {});
    // Built in the members that realiseCapture (discrete hits,
    // gridBlocksHits.C) reads after: no copy, in either collision mode
    std::vector<::dropletFiber::SampleCapture>& local = grantLocal_;
    auto& remote = grantRemote_;
    auto& askedFor = grantAskedFor_;
    askedFor.assign(outgoing_.size(), {});
    remote.assign(outgoing_.size(), {});
    forAll(outgoing_, proci)
    {
        outgoing_[proci].clear();
    }
    // P12: the demand at this block's corners, the rest asked of the owners
    attributeDemand(grid, points, massShares, strips, limit, local, askedFor);
    List<List<scalar>> requests(outgoing_.size());
    if (Pstream::parRun())
    {
        requests = exchangeLists(statistics, what);
        forAll(requests, proci)
        {
            const List<scalar>& in = requests[proci];
            const label size = grantRequestSize_;
            for (label i = 0; i + size <= in.size(); i += size)
            {
                const Eigen::Vector3d point(in[i], in[i + 1], in[i + 2]);
                const Eigen::Vector3d strip(in[i + 4], in[i + 5], in[i + 6]);
                remote[proci].push_back
                (
                    ::dropletFiber::attributeOwnedCorners
                    (
                        grid, ::dropletFiber::multilinearWeights(spec_, point),
                        in[i + 3], Eigen::Vector3d::Zero(), strip
                    )
                );
                const scalar interceptors = size > requestSize ? in[i + requestSize] : 1;
                if (size > requestSize)
                {
                    grantRemoteInterceptors_[proci].push_back(interceptors);
                }
                limit.addDemand(remote[proci].back(), interceptors);
            }
        }
    }
    // The spread populations' demand on the nodes owned here (sec. 12)
    spreadLevels_ = nullptr;
    spreadHeld_ = ::dropletFiber::LevelTable();
    spreadRegion_ = ::dropletFiber::IndexBox();
    if (spread)
    {
        spreadOntoNodes(grid, *spread, statistics);
    }
    // P13 on the nodes owned here, the parcels' removal (P14), then each
    // request's granted part back
    report = limit.limit(grid);
    captured = removeCaptured(grid, limit, parcels, dt, report, statistics);
    if (spread)
    {
        spread->grants = restrictOverBlocks(spread->demand, false, statistics);
    }
    return grantedMasses(limit, points, massShares, requests, statistics);
}


std::vector<double> Foam::dropletFiber::gridBlocks::grantedMasses
(
    const ::dropletFiber::CaptureLimit& limit,
    const std::vector<Eigen::Vector3d>& points,
    const std::vector<double>& massShares,
    const List<List<scalar>>& requests,
    parallelStatistics& statistics
)
{
    // Per corner d_sc g_c, each from the corner's owner, added in corner order: the
    // same bits whichever processors own the corners
    std::vector<std::array<double, 8>> slots(points.size(), std::array<double, 8>{});
    std::vector<int> count(points.size(), 0);
    for (std::size_t p = 0; p < points.size(); ++p)
    {
        if (massShares[p] > 0)
        {
            const auto corners = ::dropletFiber::multilinearWeights(spec_, points[p]);
            count[p] = corners.count;
            grantedSlots(limit, grantLocal_[p], corners, slots[p]);
        }
    }
    if (Pstream::parRun())
    {
        for (std::size_t proci = 0; proci < grantRemote_.size(); ++proci)
        {
            outgoing_[proci].clear();
            const List<scalar>& in = requests[proci];
            const std::size_t size = std::size_t(grantRequestSize_);
            for (std::size_t i = 0; i < grantRemote_[proci].size(); ++i)
            {
                const label at = label(size*i);
                const Eigen::Vector3d point(in[at], in[at + 1], in[at + 2]);
                const auto corners = ::dropletFiber::multilinearWeights(spec_, point);
                std::array<double, 8> answer{};
                grantedSlots(limit, grantRemote_[proci][i], corners, answer);
                if (!cornerAnswers_)
                {
                    double sum = 0;
                    for (int c = 0; c < corners.count; ++c)
                    {
                        sum += answer[c];
                    }
                    outgoing_[proci].append(sum);
                    continue;
                }
                for (int c = 0; c < corners.count; ++c)
                {
                    outgoing_[proci].append(answer[c]);
                }
            }
        }
        const List<List<scalar>> answers =
            exchangeLists(statistics, parallelStatistics::traffic::gridQueries);
        forAll(answers, proci)
        {
            label at = 0;
            for (const std::size_t p : grantAskedFor_[proci])
            {
                const int n = cornerAnswers_ ? count[p] : 1;
                for (int c = 0; c < n; ++c)
                {
                    slots[p][c] += answers[proci][at++];
                }
            }
        }
    }
    std::vector<double> granted(points.size(), 0.0);
    for (std::size_t p = 0; p < points.size(); ++p)
    {
        for (int c = 0; c < count[p]; ++c)
        {
            granted[p] += slots[p][c];
        }
    }
    return granted;
}


void Foam::dropletFiber::gridBlocks::grantedSlots
(
    const ::dropletFiber::CaptureLimit& limit,
    const ::dropletFiber::SampleCapture& capture,
    const ::dropletFiber::CornerWeights& corners,
    std::array<double, 8>& slots
)
{
    // The capture's entries are its corners with a part, in corner order: each
    // to the next corner of its node (a node twice among the corners, at a
    // folded face, keeps its two entries apart)
    int c = 0;
    for (int k = 0; k < capture.count; ++k)
    {
        while (c < corners.count && corners.node[c] != capture.node[k])
        {
            ++c;
        }
        if (c == corners.count)
        {
            break;
        }
        slots[c++] = capture.mass[k]*limit.grantedRatio(capture.node[k]);
    }
}


std::vector<double> Foam::dropletFiber::gridBlocks::removeCaptured
(
    ::dropletFiber::DensityGrid& grid,
    ::dropletFiber::CaptureLimit& limit,
    const std::vector<::dropletFiber::Parcel>& parcels,
    const double dt,
    ::dropletFiber::CaptureLimitReport& report,
    parallelStatistics& statistics
)
{
    // A_p and X_p over this block's nodes: its parcels, then the copies
    reaches_.clear();
    for (const ::dropletFiber::Parcel& parcel : parcels)
    {
        limit.reach(grid, parcel, dt, reaches_);
    }
    for (const ::dropletFiber::Parcel& copy : copies_)
    {
        limit.reach(grid, copy, dt, reaches_);
    }
    const std::size_t own = parcels.size();
    std::vector<double> saturated(own, 0.0);
    std::vector<double> depth(own, 0.0);
    std::vector<double> copySums;
    if (Pstream::parRun())
    {
        exchangeReachSums(own, copySums, statistics);
    }
    for (std::size_t p = 0; p < own; ++p)
    {
        saturated[p] = reaches_.parcels[p].saturatedSum.value();
        depth[p] = reaches_.parcels[p].depthSum.value();
    }
    // c_p from the whole sums; each block attributes the losses to its nodes
    std::vector<double> captured(own, 0.0);
    for (std::size_t p = 0; p < own; ++p)
    {
        captured[p] =
            ::dropletFiber::CaptureLimit::capturedFraction(saturated[p], depth[p]);
        if (reaches_.parcels[p].count > 0)
        {
            limit.remove
            (
                reaches_, p, ::dropletFiber::parcelMass(parcels[p]),
                saturated[p], depth[p]
            );
        }
    }
    for (std::size_t c = 0; c < copies_.size(); ++c)
    {
        if (reaches_.parcels[own + c].count > 0)
        {
            limit.remove
            (
                reaches_, own + c, ::dropletFiber::parcelMass(copies_[c]),
                copySums[2*c], copySums[2*c + 1]
            );
        }
    }
    limit.grant(report);
    keepWholeReachSums(saturated, depth, copySums);
    return captured;
}


void Foam::dropletFiber::gridBlocks::keepWholeReachSums
(
    const std::vector<double>& saturated,
    const std::vector<double>& depth,
    const std::vector<double>& copySums
)
{
    // The parcels' first, then the copies', as reached
    const std::size_t own = saturated.size();
    for (std::size_t i = 0; i < reaches_.parcels.size(); ++i)
    {
        ::dropletFiber::ParcelReach& entry = reaches_.parcels[i];
        entry.saturated = i < own ? saturated[i] : copySums[2*(i - own)];
        entry.depth = i < own ? depth[i] : copySums[2*(i - own) + 1];
    }
}


void Foam::dropletFiber::gridBlocks::exchangeReachSums
(
    const std::size_t ownParcels,
    std::vector<double>& copySums,
    parallelStatistics& statistics
)
{
    const auto what = parallelStatistics::traffic::parcels;
    constexpr label pieces = ::dropletFiber::FixedPointSum::pieceCount;
    // The copies' exact parts to their processors, in the order received
    std::size_t next = ownParcels;
    forAll(outgoing_, proci)
    {
        outgoing_[proci].clear();
        for (std::size_t i = 0; i < copiesFrom_[proci]; ++i, ++next)
        {
            const ::dropletFiber::ParcelReach& part = reaches_.parcels[next];
            for (const auto& sum : {part.saturatedSum, part.depthSum})
            {
                for (const double piece : sum.pieces())
                {
                    outgoing_[proci].append(piece);
                }
            }
        }
    }
    // Added exactly to the parcels' own parts: any order, the same bits
    const List<List<scalar>> parts = exchangeLists(statistics, what);
    forAll(parts, proci)
    {
        for (std::size_t i = 0; i < sentCopies_[proci].size(); ++i)
        {
            const scalar* in = parts[proci].cdata() + 2*pieces*i;
            ::dropletFiber::ParcelReach& whole = reaches_.parcels[sentCopies_[proci][i]];
            whole.saturatedSum.add(::dropletFiber::FixedPointSum::fromPieces(in));
            whole.depthSum.add(::dropletFiber::FixedPointSum::fromPieces(in + pieces));
        }
    }
    // The sums back to the blocks holding the copies
    forAll(outgoing_, proci)
    {
        outgoing_[proci].clear();
        for (const std::size_t p : sentCopies_[proci])
        {
            outgoing_[proci].append(reaches_.parcels[p].saturatedSum.value());
            outgoing_[proci].append(reaches_.parcels[p].depthSum.value());
        }
    }
    const List<List<scalar>> sums = exchangeLists(statistics, what);
    copySums.clear();
    forAll(sums, proci)
    {
        for (label i = 0; i < label(2*copiesFrom_[proci]); ++i)
        {
            copySums.push_back(sums[proci][i]);
        }
    }
}


// ************************************************************************* //
