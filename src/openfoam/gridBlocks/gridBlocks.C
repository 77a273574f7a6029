/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "gridBlocks.H"
#include "boundBox.H"
#include "FixedList.H"
#include "UOPstream.H"
#include "UIPstream.H"
#include "grid/MultilinearWeights.hpp"
#include "grid/DepositOrder.hpp"

#include <stdexcept>
#include <string>
#include <algorithm>
#include <unordered_map>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- This processor's subdomain bounds, every processor's (collective)
std::vector<::dropletFiber::SubdomainBounds> subdomainBounds
(
    const fvMesh& mesh
)
{
    // The local points only (mesh.bounds() is reduced over processors)
    const boundBox local(mesh.points(), false);
    List<FixedList<scalar, 6>> bounds(Pstream::nProcs());
    for (direction d = 0; d < 3; ++d)
    {
        bounds[Pstream::myProcNo()][d] = local.min()[d];
        bounds[Pstream::myProcNo()][3 + d] = local.max()[d];
    }
    Pstream::gatherList(bounds);
    Pstream::scatterList(bounds);
    std::vector<::dropletFiber::SubdomainBounds> result(bounds.size());
    forAll(bounds, proci)
    {
        for (label c = 0; c < 6; ++c)
        {
            result[proci][c] = bounds[proci][c];
        }
    }
    return result;
}


//- Numbers per parcel sent (dropletFiber::writeParcelValues' layout)
constexpr Foam::label parcelValues = ::dropletFiber::parcelValueCount;


void appendParcel
(
    DynamicList<scalar>& out,
    const ::dropletFiber::Parcel& p
)
{
    double values[parcelValues];
    ::dropletFiber::writeParcelValues(p, values);
    for (const double v : values)
    {
        out.append(v);
    }
}


::dropletFiber::Parcel readParcel(const scalar* in)
{
    return ::dropletFiber::parcelFromValues(in);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dropletFiber::gridBlocks::gridBlocks
(
    const fvMesh& mesh,
    const ::dropletFiber::GridSpec& spec
)
:
    spec_(spec),
    bisected_(false),
    balanced_(false),
    buffers_(Pstream::commsTypes::nonBlocking),
    outgoing_(Pstream::nProcs())
{
    if (!Pstream::parRun())
    {
        partition_ = ::dropletFiber::GridPartition({spec.fullBox()});
        owned_ = spec.fullBox();
        return;
    }
    const std::vector<::dropletFiber::SubdomainBounds> bounds =
        subdomainBounds(mesh);
    partition_ =
        ::dropletFiber::GridPartition::fromSubdomainBounds(spec, bounds);
    bool anyEmpty = false;
    for (const auto& box : partition_.boxes())
    {
        anyEmpty = anyEmpty || box.empty();
    }
    if (anyEmpty || !partition_.tiles(spec))
    {
        bisected_ = true;
        partition_ =
            ::dropletFiber::GridPartition::bisection(spec, Pstream::nProcs());
    }
    for (label proci = 0; proci < Pstream::nProcs(); ++proci)
    {
        if (partition_.owned(proci).empty())
        {
            throw std::invalid_argument
            (
                "the grid's " + std::to_string(spec.nodeCount())
              + " nodes cannot give each of the "
              + std::to_string(Pstream::nProcs())
              + " processors a block of its own: use more nodes (entry"
                " nodes or spacing) or fewer processors"
            );
        }
    }
    owned_ = partition_.owned(Pstream::myProcNo());
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::dropletFiber::gridBlocks::ownerOf(const std::size_t node) const
{
    const std::array<int, 3> index =
        ::dropletFiber::nodeIndicesOfFlat(spec_.nodes, node);
    return partition_.owner(index[0], index[1], index[2]);
}


Foam::List<Foam::List<Foam::scalar>>
Foam::dropletFiber::gridBlocks::exchangeLists
(
    parallelStatistics& statistics,
    const parallelStatistics::traffic what
)
{
    buffers_.clear();
    forAll(outgoing_, proci)
    {
        if (!outgoing_[proci].empty())
        {
            UOPstream os(proci, buffers_);
            os  << static_cast<const UList<scalar>&>(outgoing_[proci]);
            statistics.countSent(outgoing_[proci].byteSize(), what);
        }
    }
    labelList recvSizes;
    buffers_.finishedSends(recvSizes);
    List<List<scalar>> received(Pstream::nProcs());
    forAll(recvSizes, proci)
    {
        if (recvSizes[proci] > 0)
        {
            UIPstream is(proci, buffers_);
            is  >> received[proci];
        }
    }
    return received;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

::dropletFiber::GridBlock Foam::dropletFiber::gridBlocks::block() const
{
    // The owned nodes, stored whole: their arrays' pages become resident
    // where the deposits reach (NodeValueArray)
    return {owned_, owned_};
}


std::size_t Foam::dropletFiber::gridBlocks::largestBlockNodes() const
{
    std::size_t most = 0;
    for (const auto& box : partition_.boxes())
    {
        most = std::max(most, box.nodeCount());
    }
    return most;
}


void Foam::dropletFiber::gridBlocks::report(Ostream& os) const
{
    if (!Pstream::parRun())
    {
        return;
    }
    std::size_t fewest = spec_.nodeCount(), most = 0;
    for (const auto& box : partition_.boxes())
    {
        fewest = std::min(fewest, box.nodeCount());
        most = std::max(most, box.nodeCount());
    }
    os  << "    grid blocks: " << Pstream::nProcs() << " processors, "
        << (
               balanced_
             ? "by deposit work (recursive bisection weighted by the steady"
               " deposit's work, the restart state's partition)"
             : bisected_
             ? "by recursive bisection of the grid (the subdomains' bounding"
               " boxes do not tile it: a manual decomposition, or a grid"
               " larger than the mesh; correct, with more traffic)"
             : "from the mesh decomposition (subdomain bounding boxes)"
           )
        << ", owned nodes per processor " << label(fewest) << " to "
        << label(most) << "; parcels whose kernels reach another block are"
        << " deposited there too" << nl;
}


void Foam::dropletFiber::gridBlocks::depositCopies
(
    ::dropletFiber::DensityGrid& grid,
    const std::vector<::dropletFiber::Parcel>& parcels,
    const double dt,
    parallelStatistics& statistics,
    const std::function<void(std::size_t)>& depositOwn,
    const bool keyOrder
)
{
    cornerAnswers_ = keyOrder;
    using stage = parallelStatistics::stage;
    copies_.clear();
    copiesFrom_.assign(outgoing_.size(), 0);
    if (Pstream::parRun())
    {
        sentCopies_.resize(outgoing_.size());
        forAll(outgoing_, proci)
        {
            outgoing_[proci].clear();
            sentCopies_[proci].clear();
        }
        // The computing timed, the exchange not (parallelStatistics)
        statistics.timed(stage::deposit, [&]() { packCopies(grid, parcels, dt); });
        const List<List<scalar>> received =
            exchangeLists(statistics, parallelStatistics::traffic::parcels);
        // Kept in processor order for depletion, whose removal needs these
        // copies' weights here
        forAll(received, proci)
        {
            const List<scalar>& in = received[proci];
            for (label i = 0; i + parcelValues <= in.size(); i += parcelValues)
            {
                copies_.push_back(readParcel(in.cdata() + i));
                ++copiesFrom_[proci];
            }
        }
    }
    // Own parcels and copies in key order: every node's sum in the same
    // order on every decomposition (DepositOrder.hpp); else own parcels in
    // the cloud's order, then the copies in processor order
    statistics.timed
    (
        stage::deposit,
        [&]()
        {
            for (const auto& entry : depositSequence(parcels, keyOrder))
            {
                if (entry.copy)
                {
                    grid.depositCopy(copies_[entry.index], dt);
                }
                else
                {
                    depositOwn(entry.index);
                }
            }
        }
    );
}


std::vector<::dropletFiber::DepositEntry>
Foam::dropletFiber::gridBlocks::depositSequence
(
    const std::vector<::dropletFiber::Parcel>& parcels,
    const bool keyOrder
) const
{
    if (keyOrder)
    {
        return ::dropletFiber::depositOrder(parcels, copies_);
    }
    std::vector<::dropletFiber::DepositEntry> sequence;
    sequence.reserve(parcels.size() + copies_.size());
    for (std::size_t i = 0; i < parcels.size(); ++i)
    {
        sequence.push_back({false, i});
    }
    for (std::size_t i = 0; i < copies_.size(); ++i)
    {
        sequence.push_back({true, i});
    }
    return sequence;
}


void Foam::dropletFiber::gridBlocks::packCopies
(
    const ::dropletFiber::DensityGrid& grid,
    const std::vector<::dropletFiber::Parcel>& parcels,
    const double dt
)
{
    for (std::size_t p = 0; p < parcels.size(); ++p)
    {
        const ::dropletFiber::Parcel& parcel = parcels[p];
        const ::dropletFiber::IndexBox reached = grid.depositBox(parcel, dt);
        if (reached.intersected(owned_) == reached)
        {
            continue; // on this block only (or nowhere)
        }
        partition_.holdersOf(reached, Pstream::myProcNo(), holders_);
        for (const int proci : holders_)
        {
            appendParcel(outgoing_[proci], parcel);
            sentCopies_[proci].push_back(p);
        }
    }
}


void Foam::dropletFiber::gridBlocks::windowTotals
(
    const ::dropletFiber::DensityGrid& grid,
    const std::vector<std::size_t>& nodes,
    std::vector<double>& totals,
    parallelStatistics& statistics
)
{
    const label nQ = ::dropletFiber::nQuantities;
    totals.assign(nodes.size()*nQ, 0.0);
    // Nodes owned elsewhere: asked once each, per owner in the order met
    std::unordered_map<std::size_t, std::size_t> asked;
    std::vector<std::vector<std::size_t>> answerFor(outgoing_.size());
    std::vector<std::pair<std::size_t, std::size_t>> repeated;
    forAll(outgoing_, proci)
    {
        outgoing_[proci].clear();
    }
    for (std::size_t n = 0; n < nodes.size(); ++n)
    {
        if (grid.owns(nodes[n]))
        {
            grid.windowTotal(nodes[n], totals.data() + n*nQ);
            continue;
        }
        const auto found = asked.try_emplace(nodes[n], n);
        if (!found.second)
        {
            repeated.emplace_back(n, found.first->second);
            continue;
        }
        const label owner = ownerOf(nodes[n]);
        outgoing_[owner].append(scalar(nodes[n]));
        answerFor[owner].push_back(n);
    }
    if (!Pstream::parRun())
    {
        return;
    }
    const List<List<scalar>> requests =
        exchangeLists(statistics, parallelStatistics::traffic::gridQueries);
    forAll(requests, proci)
    {
        DynamicList<scalar>& out = outgoing_[proci];
        out.clear();
        out.setSize(requests[proci].size()*nQ);
        forAll(requests[proci], i)
        {
            grid.windowTotal(std::size_t(requests[proci][i]), out.data() + i*nQ);
        }
    }
    const List<List<scalar>> answers =
        exchangeLists(statistics, parallelStatistics::traffic::gridQueries);
    forAll(answers, proci)
    {
        for (std::size_t i = 0; i < answerFor[proci].size(); ++i)
        {
            std::copy
            (
                answers[proci].cdata() + i*nQ,
                answers[proci].cdata() + (i + 1)*nQ,
                totals.data() + answerFor[proci][i]*nQ
            );
        }
    }
    for (const auto& r : repeated)
    {
        std::copy
        (
            totals.data() + r.second*nQ,
            totals.data() + (r.second + 1)*nQ,
            totals.data() + r.first*nQ
        );
    }
}


void Foam::dropletFiber::gridBlocks::askCornerOwners
(
    const ::dropletFiber::CornerWeights& corners,
    const Eigen::Vector3d& point,
    const std::size_t sample,
    std::vector<std::vector<std::size_t>>& askedFor,
    const scalar* share
)
{
    label asked[8];
    label nAsked = 0;
    for (int c = 0; c < corners.count; ++c)
    {
        const label owner = ownerOf(corners.node[c]);
        if (owner == Pstream::myProcNo() || std::count(asked, asked + nAsked, owner))
        {
            continue;
        }
        asked[nAsked++] = owner;
        for (int d = 0; d < 3; ++d)
        {
            outgoing_[owner].append(point[d]);
        }
        if (share)
        {
            outgoing_[owner].append(*share);
        }
        askedFor[owner].push_back(sample);
    }
}


void Foam::dropletFiber::gridBlocks::answerCornerSums
(
    const ::dropletFiber::DensityGrid& grid,
    const List<List<scalar>>& questions
)
{
    // Per corner of the point's cell its term (0 where owned elsewhere): the asker adds
    // the terms in corner order, as a serial run does
    const label nQ = ::dropletFiber::nQuantities;
    forAll(questions, proci)
    {
        DynamicList<scalar>& out = outgoing_[proci];
        out.clear();
        const List<scalar>& points = questions[proci];
        for (label i = 0; i + 3 <= points.size(); i += 3)
        {
            const Eigen::Vector3d point(points[i], points[i + 1], points[i + 2]);
            CornerTerms terms{};
            const ::dropletFiber::CornerWeights corners =
                ::dropletFiber::multilinearWeights(spec_, point);
            ownedCornerTerms(grid, corners, terms);
            if (!cornerAnswers_)
            {
                std::array<double, ::dropletFiber::nQuantities> sums{};
                addCornerTerms(corners.count, terms, sums);
                out.append(UList<scalar>(sums.data(), nQ));
                continue;
            }
            for (label t = 0; t < corners.count*nQ; ++t)
            {
                out.append(terms[t]);
            }
        }
    }
}


void Foam::dropletFiber::gridBlocks::ownedCornerTerms
(
    const ::dropletFiber::DensityGrid& grid,
    const ::dropletFiber::CornerWeights& corners,
    CornerTerms& terms
)
{
    const label nQ = ::dropletFiber::nQuantities;
    for (int c = 0; c < corners.count; ++c)
    {
        if (!grid.owns(corners.node[c]))
        {
            continue;
        }
        // The one corner's weight times its window sums
        ::dropletFiber::CornerWeights one;
        one.count = 1;
        one.node[0] = corners.node[c];
        one.weight[0] = corners.weight[c];
        std::array<double, ::dropletFiber::nQuantities> term{};
        grid.addOwnedCornerSums(one, term);
        std::copy(term.begin(), term.end(), terms.begin() + c*nQ);
    }
}


void Foam::dropletFiber::gridBlocks::addCornerTerms
(
    const int count,
    const CornerTerms& terms,
    std::array<double, ::dropletFiber::nQuantities>& sums
)
{
    // In corner order from 0, on every run: serial = parallel to the bit
    const label nQ = ::dropletFiber::nQuantities;
    sums.fill(0.0);
    for (int c = 0; c < count; ++c)
    {
        for (label q = 0; q < nQ; ++q)
        {
            sums[q] += terms[c*nQ + q];
        }
    }
}


void Foam::dropletFiber::gridBlocks::addOtherOwnersSums
(
    const ::dropletFiber::DensityGrid& grid,
    const std::vector<std::vector<std::size_t>>& askedFor,
    const std::vector<::dropletFiber::CornerWeights>& cornersOf,
    parallelStatistics& statistics,
    std::vector<CornerTerms>& terms
)
{
    const label nQ = ::dropletFiber::nQuantities;
    const auto what = parallelStatistics::traffic::gridQueries;
    answerCornerSums(grid, exchangeLists(statistics, what));
    // Each corner's term comes from its one owner (0 from the others): exact
    const List<List<scalar>> answers = exchangeLists(statistics, what);
    forAll(answers, proci)
    {
        label at = 0;
        for (const std::size_t p : askedFor[proci])
        {
            // A summed answer (cornerAnswers_ off) goes into corner 0's slot
            const label n = cornerAnswers_ ? cornersOf[p].count*nQ : nQ;
            for (label t = 0; t < n; ++t)
            {
                terms[p][t] += answers[proci][at++];
            }
        }
    }
}


std::vector<::dropletFiber::DropletFieldValue>
Foam::dropletFiber::gridBlocks::sample
(
    const ::dropletFiber::DensityGrid& grid,
    const std::vector<Eigen::Vector3d>& points,
    parallelStatistics& statistics,
    std::vector<double>* massSums
)
{
    std::vector<CornerTerms> terms(points.size(), CornerTerms{});
    std::vector<bool> inside(points.size(), false);
    std::vector<std::vector<std::size_t>> askedFor(outgoing_.size());
    forAll(outgoing_, proci)
    {
        outgoing_[proci].clear();
    }
    std::vector<::dropletFiber::CornerWeights> cornersOf(points.size());
    for (std::size_t p = 0; p < points.size(); ++p)
    {
        inside[p] = ::dropletFiber::insideActiveBox(spec_, points[p]);
        if (inside[p])
        {
            cornersOf[p] = ::dropletFiber::multilinearWeights(spec_, points[p]);
        }
    }
    // This block's corners here, their window sums requested a few points
    // ahead (each corner's W slots are megabytes apart: the misses overlap);
    // the other owners of a point's corners are sent the point once each
    const std::size_t ahead = 8;
    for (std::size_t p = 0; p < std::min(ahead, points.size()); ++p)
    {
        grid.prefetchOwnedCornerSums(cornersOf[p]);
    }
    for (std::size_t p = 0; p < points.size(); ++p)
    {
        if (p + ahead < points.size())
        {
            grid.prefetchOwnedCornerSums(cornersOf[p + ahead]);
        }
        if (!inside[p])
        {
            continue;
        }
        const ::dropletFiber::CornerWeights& corners = cornersOf[p];
        ownedCornerTerms(grid, corners, terms[p]);
        if (Pstream::parRun())
        {
            askCornerOwners(corners, points[p], p, askedFor);
        }
    }
    if (Pstream::parRun())
    {
        addOtherOwnersSums(grid, askedFor, cornersOf, statistics, terms);
    }
    std::vector<std::array<double, ::dropletFiber::nQuantities>> sums
    (
        points.size()
    );
    std::vector<::dropletFiber::DropletFieldValue> values(points.size());
    for (std::size_t p = 0; p < points.size(); ++p)
    {
        values[p].inside = false;
        if (inside[p])
        {
            addCornerTerms(cornersOf[p].count, terms[p], sums[p]);
            values[p] = grid.fieldFromCornerSums(sums[p]);
        }
    }
    if (massSums)
    {
        massSums->assign(points.size(), 0.0);
        for (std::size_t p = 0; p < points.size(); ++p)
        {
            (*massSums)[p] = sums[p][::dropletFiber::quantityMass];
        }
    }
    return values;
}


void Foam::dropletFiber::gridBlocks::attributeDemand
(
    const ::dropletFiber::DensityGrid& grid,
    const std::vector<Eigen::Vector3d>& points,
    const std::vector<double>& massShares,
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
                grid, corners, massShares[p], Eigen::Vector3d::Zero()
            );
        limit.addDemand(local[p]);
        if (Pstream::parRun())
        {
            const scalar share = massShares[p];
            askCornerOwners(corners, points[p], p, askedFor, &share);
        }
    }
}


std::vector<double> Foam::dropletFiber::gridBlocks::grantCapture
(
    ::dropletFiber::DensityGrid& grid,
    const std::vector<Eigen::Vector3d>& points,
    const std::vector<double>& massShares,
    const std::vector<::dropletFiber::Parcel>& parcels,
    const double dt,
    ::dropletFiber::CaptureLimit& limit,
    ::dropletFiber::CaptureLimitReport& report,
    std::vector<double>& captured,
    parallelStatistics& statistics
)
{
    const auto what = parallelStatistics::traffic::gridQueries;
    limit.clear();
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
    attributeDemand(grid, points, massShares, limit, local, askedFor);
    List<List<scalar>> requests(outgoing_.size());
    if (Pstream::parRun())
    {
        requests = exchangeLists(statistics, what);
        forAll(requests, proci)
        {
            const List<scalar>& in = requests[proci];
            for (label i = 0; i + 4 <= in.size(); i += 4)
            {
                const Eigen::Vector3d point(in[i], in[i + 1], in[i + 2]);
                remote[proci].push_back
                (
                    ::dropletFiber::attributeOwnedCorners
                    (
                        grid, ::dropletFiber::multilinearWeights(spec_, point),
                        in[i + 3], Eigen::Vector3d::Zero()
                    )
                );
                limit.addDemand(remote[proci].back());
            }
        }
    }
    // P13 on the nodes owned here, the parcels' removal (P14), then each
    // request's granted part back
    report = limit.limit(grid);
    captured = removeCaptured(grid, limit, parcels, dt, report, statistics);
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
            for (std::size_t i = 0; i < grantRemote_[proci].size(); ++i)
            {
                const Eigen::Vector3d point(in[4*i], in[4*i + 1], in[4*i + 2]);
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
