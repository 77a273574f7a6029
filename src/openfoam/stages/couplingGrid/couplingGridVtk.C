/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
-------------------------------------------------------------------------------
Description
    The density grid as VTK image data at write times: rho, rMeanNumber,
    rMeanMass and U at every node (in parallel a piece per processor, its
    owned nodes and the layer above them, and ParaView's .pvti index).

\*---------------------------------------------------------------------------*/

#include "couplingGrid.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

std::vector<::dropletFiber::VtkField>
Foam::dropletFiber::couplingGrid::fields
(
    const ::dropletFiber::IndexBox& box,
    parallelStatistics& statistics
)
{
    const ::dropletFiber::DensityGrid& grid = *grid_;
    const auto& g = settings_.spec;
    std::vector<std::size_t> nodes;
    nodes.reserve(box.nodeCount());
    ::dropletFiber::forEachRow
    (
        box, g.nodes,
        [&nodes](const ::dropletFiber::IndexRow& row)
        {
            for (std::size_t i = 0; i < row.length; ++i)
            {
                nodes.push_back(row.first + i);
            }
        }
    );
    // One pass over the window's slots, row by row, brings the sums of every
    // owned node up to date; the per-node reads below then copy them (summed
    // node by node, each node's W slots miss the cache: ~50 ms per write of
    // the spray3D grid against ~5 ms). The same additions in the same order.
    grid.windowTotals();
    // Serial: every node is owned here, nothing is exchanged
    std::vector<double> totals;
    blocks_->windowTotals(grid, nodes, totals, statistics);
    const std::size_t n = nodes.size();
    ::dropletFiber::VtkField rho{"rho", 1, std::vector<double>(n)};
    ::dropletFiber::VtkField rNumber{"rMeanNumber", 1, std::vector<double>(n)};
    ::dropletFiber::VtkField rMass{"rMeanMass", 1, std::vector<double>(n)};
    ::dropletFiber::VtkField U{"U", 3, std::vector<double>(3*n)};
    for (std::size_t k = 0; k < n; ++k)
    {
        const ::dropletFiber::DropletFieldValue v =
            grid.nodeValueFromTotals
            (
                nodes[k], totals.data() + k*::dropletFiber::nQuantities
            );
        rho.values[k] = v.rho;
        rNumber.values[k] = v.rMeanNumber;
        rMass.values[k] = v.rMeanMass;
        for (int c = 0; c < 3; ++c)
        {
            U.values[3*k + c] = v.velocity(c);
        }
    }
    std::vector<::dropletFiber::VtkField> fields;
    fields.reserve(4);
    for (::dropletFiber::VtkField* field : {&rho, &rNumber, &rMass, &U})
    {
        fields.push_back(std::move(*field));
    }
    return fields;
}


void Foam::dropletFiber::couplingGrid::writeVtk
(
    const fileName& dir,
    const scalar t,
    ::dropletFiber::SeriesFile& series,
    parallelStatistics& statistics
)
{
    const auto& g = settings_.spec;
    Eigen::Vector3d origin, spacing;
    for (int d = 0; d < 3; ++d)
    {
        origin(d) = g.nodeCoordinate(d, 0);
        spacing(d) = g.spacing(d);  // a flat direction: its thickness
    }
    const word file = "grid_" + time_.timeName() + ".vti";
    if (!Pstream::parRun())
    {
        ::dropletFiber::writeImageData
        (
            dir/file, t, origin, spacing, g.nodes, fields(g.fullBox(), statistics)
        );
        series.add(file, t);
        return;
    }
    // A piece per processor: its owned nodes and the layer above them (owned
    // by the next processor), so that the pieces' cells tile the grid
    const auto pieceBox = [&g](const ::dropletFiber::IndexBox& owned)
    {
        ::dropletFiber::IndexBox box = owned;
        for (int d = 0; d < 3; ++d)
        {
            box.hi[d] = std::min(owned.hi[d] + 1, g.nodes[d] - 1);
        }
        return box;
    };
    const auto extent = [](const ::dropletFiber::IndexBox& box)
    {
        return ::dropletFiber::VtkExtent
        {{box.lo[0], box.hi[0], box.lo[1], box.hi[1], box.lo[2], box.hi[2]}};
    };
    const auto pieceFile = [this](const label proci)
    {
        return word("grid_" + time_.timeName() + "_" + Foam::name(proci) + ".vti");
    };
    const ::dropletFiber::IndexBox mine = pieceBox(grid_->ownedBox());
    const std::vector<::dropletFiber::VtkField> pieceFields = fields(mine, statistics);
    ::dropletFiber::writeImageDataPiece
    (
        dir/pieceFile(Pstream::myProcNo()), t, origin, spacing, extent(mine), pieceFields
    );
    if (Pstream::master())
    {
        std::vector<::dropletFiber::VtkPiece> pieces;
        for (label proci = 0; proci < Pstream::nProcs(); ++proci)
        {
            pieces.push_back
            (
                {extent(pieceBox(blocks_->partition().owned(proci))), pieceFile(proci)}
            );
        }
        const word index = "grid_" + time_.timeName() + ".pvti";
        ::dropletFiber::writePImageData
        (
            dir/index, t, origin, spacing, extent(g.fullBox()), pieceFields, pieces
        );
        series.add(index, t);
    }
}


// ************************************************************************* //
