/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "gridBlocks.H"
#include "boundBox.H"
#include "FixedList.H"
#include "UOPstream.H"
#include "UIPstream.H"
#include "grid/MultilinearWeights.hpp"

#include <stdexcept>
#include <string>
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


//- A box as six values (an empty box: 0 0 0 -1 -1 -1)
void appendBox(DynamicList<scalar>& out, const ::dropletFiber::IndexBox& box)
{
    for (int d = 0; d < 3; ++d)
    {
        out.append(box.empty() ? 0 : box.lo[d]);
    }
    for (int d = 0; d < 3; ++d)
    {
        out.append(box.empty() ? -1 : box.hi[d]);
    }
}


::dropletFiber::IndexBox readBox(const UList<scalar>& in)
{
    ::dropletFiber::IndexBox box;
    for (int d = 0; d < 3; ++d)
    {
        box.lo[d] = int(in[d]);
        box.hi[d] = int(in[3 + d]);
    }
    return box;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dropletFiber::gridBlocks::gridBlocks
(
    const fvMesh& mesh,
    const ::dropletFiber::GridSpec& spec,
    const label halo
)
:
    spec_(spec),
    bisected_(false),
    halo_(halo),
    buffers_(Pstream::commsTypes::nonBlocking),
    outgoing_(Pstream::nProcs())
{
    if (!Pstream::parRun())
    {
        partition_ = ::dropletFiber::GridPartition({spec.fullBox()});
        storage_ = spec.fullBox();
        shared_.assign(1, ::dropletFiber::IndexBox{});
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
    storage_ = partition_.storageBox(spec, Pstream::myProcNo(), int(halo));
    shared_.assign(Pstream::nProcs(), ::dropletFiber::IndexBox{});
    for (const auto& n : partition_.neighbours(Pstream::myProcNo(), storage_))
    {
        shared_[n.processor] = n.shared;
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::dropletFiber::gridBlocks::ownerOf(const std::size_t node) const
{
    const std::size_t nx = std::size_t(spec_.nodes[0]);
    const std::size_t ny = std::size_t(spec_.nodes[1]);
    return partition_.owner
    (
        int(node % nx), int((node/nx) % ny), int(node/(nx*ny))
    );
}


Foam::List<Foam::List<Foam::scalar>>
Foam::dropletFiber::gridBlocks::exchangeLists(parallelStatistics& statistics)
{
    buffers_.clear();
    forAll(outgoing_, proci)
    {
        if (!outgoing_[proci].empty())
        {
            UOPstream os(proci, buffers_);
            os  << static_cast<const UList<scalar>&>(outgoing_[proci]);
            statistics.countSent(outgoing_[proci].byteSize());
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
    const label me = Pstream::parRun() ? Pstream::myProcNo() : 0;
    return {partition_.owned(me), storage_};
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
               bisected_
             ? "by recursive bisection of the grid (the subdomains' bounding"
               " boxes do not tile it: a manual decomposition, or a grid"
               " larger than the mesh; correct, with more traffic)"
             : "from the mesh decomposition (subdomain bounding boxes)"
           )
        << ", owned nodes per processor " << label(fewest) << " to "
        << label(most) << ", halo " << halo_ << " nodes" << nl;
}


void Foam::dropletFiber::gridBlocks::sumStep
(
    ::dropletFiber::DensityGrid& grid,
    parallelStatistics& statistics
)
{
    if (!Pstream::parRun())
    {
        return;
    }
    const label nQ = ::dropletFiber::nQuantities;
    const std::vector<::dropletFiber::OverflowNode> overflow = grid.takeOverflow();
    std::vector<std::vector<const ::dropletFiber::OverflowNode*>> overflowTo
    (
        Pstream::nProcs()
    );
    for (const auto& entry : overflow)
    {
        overflowTo[ownerOf(entry.node)].push_back(&entry);
    }
    // Per owner: the touched part of the halo it owns (box, values), then
    // the overflow entries (node, values)
    const ::dropletFiber::IndexBox touched = grid.stepBox();
    forAll(outgoing_, proci)
    {
        DynamicList<scalar>& out = outgoing_[proci];
        out.clear();
        const ::dropletFiber::IndexBox box = shared_[proci].intersected(touched);
        if (box.empty() && overflowTo[proci].empty())
        {
            continue;
        }
        appendBox(out, box);
        const label start = out.size();
        out.setSize(start + label(box.nodeCount())*nQ);
        grid.packStep(box, out.data() + start);
        for (const auto* entry : overflowTo[proci])
        {
            out.append(scalar(entry->node));
            for (label q = 0; q < nQ; ++q)
            {
                out.append(entry->values[q]);
            }
        }
    }
    const List<List<scalar>> received = exchangeLists(statistics);
    // Added in processor order: the same sums on every run
    forAll(received, proci)
    {
        const List<scalar>& in = received[proci];
        if (in.empty())
        {
            continue;
        }
        const ::dropletFiber::IndexBox box = readBox(in);
        const label haloValues = label(box.nodeCount())*nQ;
        grid.addStep(box, in.cdata() + 6, std::size_t(haloValues));
        for (label i = 6 + haloValues; i + nQ < in.size() + 1; i += nQ + 1)
        {
            grid.addToNode(std::size_t(in[i]), in.cdata() + i + 1);
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
    const List<List<scalar>> requests = exchangeLists(statistics);
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
    const List<List<scalar>> answers = exchangeLists(statistics);
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


std::vector<::dropletFiber::DropletFieldValue>
Foam::dropletFiber::gridBlocks::sample
(
    const ::dropletFiber::DensityGrid& grid,
    const std::vector<Eigen::Vector3d>& points,
    parallelStatistics& statistics
)
{
    const label nQ = ::dropletFiber::nQuantities;
    // The corners of every point inside the box, in order
    std::vector<std::size_t> corners;
    for (const Eigen::Vector3d& point : points)
    {
        if (::dropletFiber::insideActiveBox(spec_, point))
        {
            const ::dropletFiber::CornerWeights w =
                ::dropletFiber::multilinearWeights(spec_, point);
            corners.insert(corners.end(), w.node.begin(), w.node.begin() + w.count);
        }
    }
    std::vector<double> totals;
    windowTotals(grid, corners, totals, statistics);

    // The values, as DensityGrid::sample forms them
    std::vector<::dropletFiber::DropletFieldValue> values(points.size());
    std::size_t corner = 0;
    for (std::size_t p = 0; p < points.size(); ++p)
    {
        if (!::dropletFiber::insideActiveBox(spec_, points[p]))
        {
            values[p].inside = false;
            continue;
        }
        const ::dropletFiber::CornerWeights w =
            ::dropletFiber::multilinearWeights(spec_, points[p]);
        values[p] = grid.interpolated(w, totals.data() + corner*nQ);
        corner += std::size_t(w.count);
    }
    return values;
}

// ************************************************************************* //
