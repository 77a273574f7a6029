/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "gridBlocks.H"
#include "levelSums.H"
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
    return
        ::Foam::dropletFiber::exchangeLists
        (
            outgoing_, buffers_, statistics, what
        );
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
    const scalar* extra,
    const label nExtra
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
        for (label e = 0; e < nExtra; ++e)
        {
            outgoing_[owner].append(extra[e]);
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


// ************************************************************************* //
