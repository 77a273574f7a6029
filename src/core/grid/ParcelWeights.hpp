// ParcelWeights: the weights of one parcel on the grid's nodes (docs/model.md sec. 4,
// eqs. 12-24, P10, P16), the deposit's steps 3-6, without storage of node values: it
// chooses how to weigh the parcel and hands the weights to a WeightSink (the step values,
// or the sums of depletion).
//  3. Kernel (ParcelKernel, eqs. 12-18), reach = r_max or the cap. When the cap binds,
//     StepStatistics::parcelsCapped counts it (the caller can warn). A kernel narrower
//     than KernelSettings::cloudInCellBelow times the largest spacing is not resolved by
//     the grid: the parcel goes to the cell corners (CloudInCellWeights;
//     parcelsCloudInCell).
//  4. Every node of the unbounded lattice lower + i h (NodeLattice) in the bounding box of
//     the capsule swept by the clipped path (within reach of the path; ghost nodes beyond
//     the faces included, up to one grid length) gets omega_g (PathWeight, eq. 23); nodes
//     farther than reach from the path are rejected before any exp/erf. Nodes whose weight
//     would be below KernelSettings::negligibleWeight times the parcel's largest are left
//     out too (the capsule shrinks to that distance, P10). Cost per parcel ~ nodes in that
//     box, independent of the grid size (StepStatistics::nodesVisited). The exact weights
//     come from LatticeWeights (batched AVX2 + FMA or node by node). Wide kernels (reach
//     after the cut >= separableFromSpacings spacings; KernelSettings::method automatic)
//     get separable weights instead (SeparableWeight: per-axis tables, Gauss-Legendre along
//     the path, ghost nodes folded per axis) where its bound keeps them within 1e-7 of the
//     parcel's largest weight; the same box, every node of it weighed, the normalising sum
//     from the tables' per-axis sums (P16).
//  5. Weights w_g = omega_g / sum omega (eq. 24, the sum over the lattice nodes), each
//     ghost node's weight added to its mirror image across the face (folded kernels): the
//     mass given to the grid is f times the parcel's mass to round-off. A parcel whose box
//     has no ghost node gets eqs. 23-24 unchanged.
//  6. Fallback when sum omega == 0: cloud-in-cell weights (CloudInCellWeights;
//     StepStatistics::parcelsFallback).
// The separable tables of the parcels whose weighted box meets a region the caller names
// are kept from the deposit for the removal of the same step (KeptTables), which reads
// them instead of rebuilding them: the same tables, so the same sums to the bit.
#pragma once

#include "grid/CloudInCellWeights.hpp"
#include "grid/KeptTables.hpp"
#include "grid/LatticeWeights.hpp"
#include "grid/NodeLattice.hpp"
#include "grid/Parcel.hpp"
#include "grid/ParcelKernel.hpp"
#include "grid/ParcelPath.hpp"
#include "grid/SeparableWeight.hpp"
#include "grid/WeightSink.hpp"

namespace dropletFiber
{

class ParcelWeights
{
public:
    // spec validated by the caller; throws std::invalid_argument on invalid settings.
    ParcelWeights(const GridSpec& spec, const KernelSettings& kernel);

    const NodeLattice& lattice() const { return lattice_; }
    const KernelSettings& kernelSettings() const { return kernelSettings_; }
    int kernelDimension() const { return kernelDimension_; } // 2 or 3, the r_min formula in use
    // KernelSettings::vectorised and a CPU with AVX2 + FMA (KernelBuild.hpp).
    bool batched() const { return batched_; }

    // Steps 3-6: the weights of the parcel's clipped path into the sink.
    void weigh(const Parcel& parcel, const ClippedPath& path, WeightSink& sink);
    // A box (grid indices) holding every node weigh() can give weight to: the kernel's
    // nodes (folded) and those of its cloud-in-cell fallback.
    IndexBox box(const Parcel& parcel, const ClippedPath& path) const;

    // The tables kept for the removal (KeptTables::setRegion, clear).
    KeptTables& keptTables() { return kept_; }
    const KeptTables& keptTables() const { return kept_; }

private:
    // Distance from the path beyond which a node's weight is below
    // KernelSettings::negligibleWeight times the parcel's largest (<= reach; P10).
    double negligibleDistance(const ParcelKernel& kernel, double pathLength) const;
    // Gauss-Legendre points for the separable weights of this parcel, 0 for the exact
    // code: KernelSettings::method, a kernel reaching (cut-off included) at least
    // separableFromSpacings largest spacings, and SeparableWeight's bound with every node
    // of the box weighed (no threshold).
    int separablePoints(const PathWeight& pathWeight, std::size_t boxNodes) const;
    // Step 4 for wide kernels: the kept tables where the parcel has them (kept: a sparse
    // sink's find), built otherwise (folded where the box has ghost nodes; weightedBox: the
    // folded box) and kept where the deposit is to keep them. tables: those to weigh with;
    // returns sum omega over the lattice box, from the tables' per-axis sums.
    double separableTables(const KeptTables::Key& key, const KeptTables::Entry* kept,
                           const PathWeight& pathWeight, const ClippedPath& path, const IndexBox& box,
                           int points, WeightSink& sink, IndexBox& weightedBox, SeparableTables& tables);
    // Kernels reaching fewer spacings keep the exact code: at reach 1-2 spacings the
    // separable weights were 0.7-1.1x the exact code's speed (stationary; moving ones mostly
    // fail the bound: a path of h/2 is long against such a kernel), at 3.3 spacings 1.3-2.6x
    // (wideKernelBench).
    static constexpr double separableFromSpacings = 3.0;

    NodeLattice lattice_;
    KernelSettings kernelSettings_;
    int kernelDimension_;
    bool batched_;
    LatticeWeights exact_;           // the exact code's weights of the current parcel
    CloudInCellWeights cloudInCell_; // the cloud-in-cell weights of the current parcel
    SeparableWeight separable_;      // wide kernels' per-axis tables
    MirrorImages separableMirror_;   // the folding of the separable tables' box
    KeptTables kept_;                // the tables kept for the removal
};

} // namespace dropletFiber
