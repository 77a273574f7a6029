// DensityGrid: droplet mass density, mean radius and mean velocity on a regular grid,
// from parcels (docs/model.md sec. 4, eqs. 19-26). Per time step:
//     for each parcel: deposit(parcel, dt)     -> the step's accumulator
//     commitStep()                              -> the step enters the averaging window
//     nodeValue(i, j, k), sample(point)         -> fields averaged over the window
//
// One parcel's mass, step by step (deposit):
//  1. Path: from position - velocity dt to position (Parcel.hpp convention).
//  2. The path is clipped to the grid box (flat directions: the slab [lower, upper]).
//     The parcel puts the fraction f of its mass on the grid that equals the fraction of
//     the step it spends inside the box; the rest is reported as mass outside. So a parcel
//     entirely outside gives nothing (even if its kernel would reach nodes: piling the
//     mass of droplets outside onto the edge nodes would bias them), and a parcel
//     crossing the boundary gives the time-averaged share of eq. 26.
//  3. Kernel (ParcelKernel, eqs. 12-18), reach = r_max or the cap. When the cap binds,
//     StepStatistics::parcelsCapped counts it (the caller can warn). A kernel narrower
//     than KernelSettings::cloudInCellBelow times the largest spacing is not resolved by
//     the grid: the parcel goes to the cell corners as in 6 (parcelsCloudInCell).
//  4. Every node of the unbounded lattice lower + i h in the bounding box of the capsule
//     swept by the clipped path (within reach of the path; ghost nodes beyond the faces
//     included, up to one grid length) gets omega_g (PathWeight, eq. 23); nodes farther than reach from
//     the path are rejected before any exp/erf. Nodes whose weight would be below
//     KernelSettings::negligibleWeight (1e-17) times the parcel's largest are left out too
//     (the capsule shrinks to that distance; kernels of large alpha). Cost per parcel ~ nodes in that box,
//     independent of the grid size (StepStatistics::nodesVisited counts them). Moving
//     parcels' weights come from the batched AVX2 + FMA loop (PathWeightBatch) where the
//     CPU has it and KernelSettings::vectorised is set (batchedKernel(); boxes of at least
//     PathWeightBatch::minimumBoxNodes nodes), else node by node:
//     the same nodes, boxes and statistics, weights equal to ~1 ulp of exp/erfc.
//     Wide kernels (reach after the cut >= separableFromSpacings spacings;
//     KernelSettings::method automatic) get separable weights instead (SeparableWeight:
//     per-axis tables, Gauss-Legendre along the path, ghost nodes folded per axis) where
//     its bound keeps them within 1e-7 of the parcel's largest weight; the same box, every
//     node of it weighed, the normalising sum from the tables' per-axis sums, and the
//     weights accumulated row by row over the stored part of the box (docs/model.md P16).
//  5. Weights w_g = omega_g / sum omega (eq. 24, the sum over the lattice nodes), and each
//     ghost node's weight added to its mirror image across the face (folded kernels,
//     GridSpec::mirrorIndex): the mass given to the grid is f times the parcel's mass to
//     round-off. A parcel whose box has no ghost node gets eqs. 23-24 unchanged.
//  6. Fallback when sum omega == 0 (r_max smaller than the distance from the path to
//     every node, e.g. n = 1, or only weights that underflow): the mass goes to the cell
//     corners with multilinear (cloud-in-cell) weights, averaged over points spaced at
//     most half a node spacing along the path (1/16 where the path's cells touch a face
//     node, faceRefinement). Mass is conserved;
//     StepStatistics::parcelsFallback counts these parcels.
//  7. Per node: mass w f n m, droplet count w f n, count*radius, mass*radius, mass*velocity
//     (GridQuantities.hpp).
//
// Fields from the window (last W committed steps, equal weight per step, eq. 26), at a
// node with window sums S_q over s steps (s = min(committed, W)) and node volume V (the
// dual cell, GridSpec::dualVolume):
//     rho = S_mass / (V s),  number density = S_count / (V s),
//     rMeanNumber = S_countRadius / S_count (eq. 10),  rMeanMass = S_massRadius / S_mass,
//     velocity = S_momentum / S_mass (mass-weighted mean droplet velocity).
// Empty nodes give zeros. sample(point) interpolates the densities S_q / V multilinearly
// and then forms the same ratios: rho and the momentum density are exactly
// bilinear/trilinear between nodes, and the means are not dragged to zero by empty
// neighbours.
// Points outside the box (in active directions) give inside = false and zeros.
//
// Edge nodes (docs/model.md sec. 4): node volumes of the dual cells (half a cell on a face
// of the box, a quarter on an edge, an eighth at a corner; active directions only) and
// folded kernels (step 5) together make a uniform spray filling the box read its density
// at every node, faces, edges and corners included (EdgeNodesTest). Cloud-in-cell
// deposits need no folding (the corners of a point inside the box are nodes).
//
// Blocks (parallel runs, MPI done by the caller; docs/model.md sec. 4, grid blocks): a
// grid may hold a block of the global lattice only (GridBlock): the nodes it owns, where
// its averaging window lives, and the nodes it stores the step's deposit for (normally
// the same box). All lattice arithmetic (path clipping at the global box, kernels,
// weights normalised over the global lattice, folding, node volumes) is that of the whole
// grid; only storage and indexing are local, so a block deposits exactly what the whole
// grid would at the nodes it stores, and leaves the other nodes to the blocks that store
// them. The caller gives every parcel to each block its deposit reaches (depositBox):
// the block whose processor holds the parcel calls deposit(), which counts it in the step
// statistics; the others call depositCopy(), which does not. Summed over the blocks, each
// node gets every parcel's weight once, the same weight the whole grid gives it. Then
// commitStep(): the owned part of the step enters the window. Queries: windowTotal() at
// an owned node; addOwnedCornerSums() gives a block's share of sample()'s sums at a point,
// and the shares of the blocks owning its corners add up to them. With the whole grid as the block (the default)
// nothing changes.
//
// Depletion (docs/model.md sec. 7): depositedShare() re-evaluates a parcel's weights by
// deposit()'s own code path (steps 1-6 send them to a sink: the step accumulator, or a
// sum weighted per node), lastStepValue() reads what the newest committed step deposited.
// The separable tables of the parcels whose weighted box meets a region the caller names
// (keepTablesNear: where the fibers may take) are kept from the deposit until the next
// step's first deposit, and the sparse depositedShare reads them instead of rebuilding them
// (KeptTables.hpp; the same tables, so the same sums to the bit).
//
// Restart: saveWindow()/restoreWindow(). The state is the deposit log (DepositLog.hpp):
// every parcel deposit() and depositCopy() put on the grid in the window's steps, in
// order, with its dt; restoring replays it (each parcel deposited again as a copy, step by
// step, oldest first, each step committed), which rebuilds slots and total bit for bit
// with the same kernel settings, grid and code. Where a step's values were written rather
// than deposited (unpackStep, the non-const stepValues()), the window's node values are
// saved instead (AveragingWindow.hpp) until W deposited steps have followed; both formats
// are read. The restored grid gives bit-for-bit the same fields and the same results for
// later steps.
//
// Invalid parcels (non-finite values, negative diameter/nParticle/density) and dt < 0
// throw std::invalid_argument; nParticle == 0 or diameter == 0 is counted and skipped.
//
// Memory: nQuantities = 7 doubles (56 bytes) per node for the step accumulator (per
// stored node), the window total and each of the W window slots (allocated as the window
// fills; per owned node): (W + 2) * 56 bytes per node for the whole grid, e.g.
// 250 x 250 nodes, W = 10: 42 MB. The deposit log: 72 bytes per parcel deposited on
// the grid in each of the W (+1) steps, e.g. 4,000 parcels per step, W = 10: 3.2 MB.
// Time per parcel: ~ nodes within reach of its path (one erf-type evaluation each).
#pragma once

#include "grid/AveragingWindow.hpp"
#include "grid/DepositLog.hpp"
#include "grid/GridQuantities.hpp"
#include "grid/GridSpec.hpp"
#include "grid/KeptTables.hpp"
#include "grid/MultilinearWeights.hpp"
#include "grid/Parcel.hpp"
#include "grid/ParcelKernel.hpp"
#include "grid/PathWeight.hpp"
#include "grid/PathWeightBatch.hpp"
#include "grid/SeparableWeight.hpp"
#include "grid/SparseNodeValues.hpp"
#include "grid/StepStatistics.hpp"

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <functional>
#include <unordered_map>
#include <utility>
#include <vector>

namespace dropletFiber
{

// Droplet field at a node or interpolated at a point.
struct DropletFieldValue
{
    bool inside = true;                      // false: point outside the grid box, all zeros
    double rho = 0.0;                        // droplet mass per volume of space, kg/m^3
    double numberDensity = 0.0;              // droplets per volume, 1/m^3
    double rMeanNumber = 0.0;                // number-weighted mean droplet radius (eq. 10), m
    double rMeanMass = 0.0;                  // mass-weighted mean droplet radius, m
    Eigen::Vector3d velocity{0.0, 0.0, 0.0}; // mass-weighted mean droplet velocity, m/s
};

// The part of the grid one DensityGrid holds: the nodes it owns (its averaging window)
// and the nodes it stores the step's deposit for (normally the owned nodes), grid indices.
struct GridBlock
{
    IndexBox owned;
    IndexBox storage;
};

class DensityGrid
{
public:
    // windowLength W >= 1: number of committed steps averaged. Throws std::invalid_argument
    // on an invalid spec or settings.
    DensityGrid(const GridSpec& spec, const KernelSettings& kernel = KernelSettings{}, int windowLength = 1);
    // A block of the grid: block.owned non-empty, inside block.storage, inside the grid.
    DensityGrid(const GridSpec& spec, const KernelSettings& kernel, int windowLength, const GridBlock& block);

    const GridSpec& spec() const { return spec_; }
    const KernelSettings& kernelSettings() const { return kernelSettings_; }
    int kernelDimension() const { return kernelDimension_; } // 2 or 3, the r_min formula in use
    // True when deposit() evaluates moving parcels with the batched AVX2 + FMA node loop:
    // KernelSettings::vectorised and a CPU that has it (KernelBuild.hpp).
    bool batchedKernel() const { return batched_; }

    // --- one time step ---------------------------------------------------------------
    void deposit(const Parcel& parcel, double dt);
    // A parcel another block holds and deposits (see Blocks above): the same deposit onto
    // the nodes stored here, counted in copyStatistics() instead of stepStatistics().
    void depositCopy(const Parcel& parcel, double dt);
    // Ends the step: the accumulator enters the window and is cleared; statistics move
    // to lastStepStatistics().
    void commitStep();
    const StepStatistics& stepStatistics() const { return stepStatistics_; }
    const StepStatistics& lastStepStatistics() const { return lastStepStatistics_; }
    // What depositCopy() did this step (cleared by commitStep()).
    const StepStatistics& copyStatistics() const { return copyStatistics_; }

    // --- the deposit's weights re-evaluated (depletion, docs/model.md sec. 7) ------------
    // A value per global flat node index.
    using NodeFraction = std::function<double(std::size_t)>;
    // True when a box of nodes (grid indices) may hold a node whose fraction is not 0.
    using NodeBoxTest = std::function<bool(const IndexBox&)>;
    // sum over the nodes n of the share of the parcel's mass deposit(parcel, dt) gives n
    // (w_n f: eq. 24's weight, folded, or the cloud-in-cell weight, times the part f of the
    // step inside the box) times fraction(n); nothing is accumulated, the statistics stay
    // as they are. The same code path as deposit(), so the weights are the deposit's to the
    // bit. A parcel whose nodes (and those of its cloud-in-cell fallback) `asks` turns down
    // gives 0 before any weight is evaluated (cheap where few nodes have a fraction).
    // The weights cover the whole grid whatever the block (fraction() decides which nodes
    // count): blocks that each ask for their owned nodes give parts that add up. `region`
    // holds every node whose fraction may be non-zero: separable weights are evaluated
    // there only (the same weights; the sum only skips terms that are 0).
    double depositedShare(const Parcel& parcel, double dt, const NodeBoxTest& asks,
                          const NodeFraction& fraction, const IndexBox& region);
    // The same with the fractions of a few nodes (0 at the others; region: their box), to the
    // bit: the sum skips only terms that are 0, and adds the others in the same order.
    // Visits those nodes only: separable weights evaluated per node (SeparableWeight::omega),
    // the exact code's weighted nodes merged with them (both in node order), no per-node call.
    double depositedShare(const Parcel& parcel, double dt, const NodeBoxTest& asks,
                          const SparseNodeValues& fractions);
    // The deposits from now on keep the separable tables of the parcels whose (folded)
    // weighted box meets `region` (grid indices; empty: none, the default), for the sparse
    // depositedShare of the same step (KeptTables.hpp). Only the time of depositedShare
    // depends on the region, never a result.
    void keepTablesNear(const IndexBox& region) { kept_.setRegion(region); }
    // The tables the last step's deposits kept (their number and bytes).
    const KeptTables& keptTables() const { return kept_; }
    // A box (grid indices) holding every node deposit(parcel, dt) can give mass to: the
    // kernel's nodes (folded) and those of its cloud-in-cell fallback; empty when the
    // parcel gives the grid nothing. A parallel caller sends a parcel to the blocks whose
    // owned nodes this box meets (deposit), or whose nodes of interest
    // (CaptureLimit::takenBox) it meets (depletion).
    IndexBox depositBox(const Parcel& parcel, double dt) const;
    // Quantity q of the newest committed step at an owned node (global flat index): what
    // the step's parcels, summed over the blocks, deposited there; 0 before any commit.
    double lastStepValue(std::size_t node, int q) const;

    // --- step accumulator and the block's exchanges -------------------------------------
    const IndexBox& ownedBox() const { return owned_; }
    const IndexBox& storageBox() const { return storage_; }
    // storage.nodeCount() * nQuantities doubles, GridQuantities layout over the storage box
    // (flatIndexInBox; the whole grid: flat node index), zero outside stepBox(). The
    // vector's storage may change at commitStep() (it can become a window slot): take
    // data() anew after each commit. Writing through the non-const accessor (or
    // unpackStep) makes the step one that the deposit log cannot replay: saveWindow() then
    // saves node values until W deposited steps have followed.
    std::vector<double>& stepValues()
    {
        log_.markIncomplete();
        clearPendingRows();
        return step_;
    }
    const std::vector<double>& stepValues() const
    {
        clearPendingRows();
        return step_;
    }
    // The stored nodes the step touched (grid indices).
    IndexBox stepBox() const { return stepBox_; }
    // Copies the box's values (nQuantities per node, i fastest; the box inside the storage
    // box) into a contiguous buffer...
    std::vector<double> packStep(const IndexBox& box) const;
    // The same into the caller's buffer of box.nodeCount() * nQuantities values (the
    // function object packs straight into its message).
    void packStep(const IndexBox& box, double* values) const;
    // ...and back: overwrites the box (e.g. with the sum over ranks); stepBox() becomes
    // stepBox() united with box. Nodes outside the box are left as they are.
    void unpackStep(const IndexBox& box, const std::vector<double>& values);
    void unpackStep(const IndexBox& box, const double* values, std::size_t count);

    // --- averaging window and fields ----------------------------------------------------
    int windowLength() const { return window_.length(); }
    int stepsInWindow() const { return window_.filled(); }
    std::int64_t committedSteps() const { return window_.committedSteps(); }
    const std::vector<double>& windowTotals() const { return window_.total(); }
    // The window's restart state: the deposit log of its steps (DepositLog, formats 3 and
    // 4), or its node values (AveragingWindow, formats 1 and 2): the smaller of the two
    // (Smaller), or the one asked for; node values where a step in the window was not
    // deposited (the log cannot replay it).
    enum class WindowStateFormat
    {
        Smaller,
        DepositLog,
        NodeValues
    };
    WindowState saveWindow(WindowStateFormat format = WindowStateFormat::Smaller) const;
    // The window's node values (formats 1 and 2), whatever the log holds (inspection).
    WindowState saveWindowValues() const { return window_.save(); }
    // Either format. A log is replayed: its parcels deposited again as copies, step by
    // step, oldest first, each step committed (the newest min(saved, W) steps): the same
    // slots and total bit for bit, given the same kernel settings, grid and code. A state
    // of a larger block (a serial run's whole grid) gives a block its part, as node values
    // do. Called before the step's deposits (throws std::invalid_argument otherwise, and
    // when the state does not fit this grid). The last step's statistics are kept.
    void restoreWindow(const WindowState& state);
    // Parcels in the deposit log's committed steps.
    std::size_t loggedParcels() const { return log_.loggedParcels(); }

    // Fields at an owned node (grid indices / global flat index).
    DropletFieldValue nodeValue(int i, int j, int k) const;
    DropletFieldValue nodeValue(std::size_t flatIndex) const;
    // nodeValue() from the node's window sums S_q (nQuantities values, wherever read).
    DropletFieldValue nodeValueFromTotals(std::size_t flatIndex, const double* sums) const;
    // The field at a point whose cell corners are owned here (all of them for the whole
    // grid); throws std::out_of_range otherwise.
    DropletFieldValue sample(const Eigen::Vector3d& point) const;
    // The window sums S_q of an owned node (global flat index), nQuantities values.
    void windowTotal(std::size_t node, double* sums) const;
    bool owns(std::size_t node) const;
    // The sums sample() interpolates (per corner: weight x window sums per whole cell), over
    // the corners owned here only, added to `sums` in corner order. Summed over the blocks
    // that own a point's corners, they are sample()'s sums; fieldFromCornerSums() then gives
    // its value (the whole grid: the same arithmetic, in the same order, to the bit).
    void addOwnedCornerSums(const CornerWeights& corners, std::array<double, nQuantities>& sums) const;
    // Requests the memory addOwnedCornerSums(corners, ...) will read: called a few points
    // ahead, it overlaps their cache misses (AveragingWindow::prefetchNodeTotal).
    void prefetchOwnedCornerSums(const CornerWeights& corners) const;
    DropletFieldValue fieldFromCornerSums(const std::array<double, nQuantities>& sums) const
    {
        return fieldFromSums(sums);
    }
    // sample()'s value from the window sums of the corners (corner c's nQuantities values
    // at cornerTotals + c * nQuantities): the same arithmetic, in the same order.
    DropletFieldValue interpolated(const CornerWeights& corners, const double* cornerTotals) const;
    // Each corner's part of the interpolated mass sum that gives sample()'s rho (the
    // corner weight times the corner's window mass per whole cell), into parts[c]; returns
    // their sum, rho times (node volume x steps in the window): the same arithmetic, in the
    // same order, as interpolated().
    double densityParts(const CornerWeights& corners, const double* cornerTotals, double* parts) const;
    // Window mass per step on the owned nodes: sum over them of S_mass / s (kg).
    double windowMassPerStep() const;

private:
    // The part of a parcel's path inside the grid box (deposit steps 1-2), on the node
    // layer in flat directions; fraction: the share of the step spent inside the box.
    struct ClippedPath
    {
        Eigen::Vector3d start{0.0, 0.0, 0.0};
        Eigen::Vector3d displacement{0.0, 0.0, 0.0};
        double fraction = 0.0;
    };

    // Corner c's share of sample()'s sums: weight x window sums per whole cell.
    void addCornerSum(const CornerWeights& corners, int c, const double* total,
                      std::array<double, nQuantities>& sums) const;
    // Window sums S_q per whole cell volume (any weights) -> field values.
    DropletFieldValue fieldFromSums(const std::array<double, nQuantities>& sums) const;
    // Whole cells per dual-cell volume of the node: 1 inside, 2 on a face, 4 on an edge,
    // 8 at a corner (GridSpec::dualVolume).
    double cellsPerNodeVolume(std::size_t flatIndex) const;
    // Coordinates of the lattice nodes in direction d, indexed by lattice index (node 0
    // at 0; ghost nodes from -ghostLayers_[d] to nodes - 1 + ghostLayers_[d]).
    const double* latticeCoordinates(int d) const
    {
        return coordinates_[static_cast<std::size_t>(d)].data() + ghostLayers_[static_cast<std::size_t>(d)];
    }

    // --- deposit(), in the order of its steps (top of this file) ------------------------
    // Where a parcel's weights go (steps 4-7): the step accumulator, the parcel's quantities
    // times the weight (deposit), or a sum of weight times fraction(node) (depositedShare).
    struct WeightSink
    {
        StepStatistics& statistics;
        const std::array<double, nQuantities>* totals; // deposit: the parcel's quantities
        const NodeBoxTest* asks;                       // depositedShare: boxes that may matter
        const NodeFraction* fraction;                  // depositedShare: per node
        double sum;                                    // depositedShare: sum weight * fraction
        IndexBox region;                               // depositedShare: nodes with a fraction
        const SparseNodeValues* sparse = nullptr;      // depositedShare: the fractions, if sparse
        bool accumulates() const { return totals != nullptr; }
        bool wants(const IndexBox& box) const { return asks == nullptr || (!box.empty() && (*asks)(box)); }
    };

    // depositedShare's steps: deposit()'s, the weights into the sink's sum.
    double shareOf(const Parcel& parcel, double dt, WeightSink& sink);
    // Steps 1-2: clips the parcel's path and books the mass outside the box in stats; false
    // when nothing of the parcel is to be deposited.
    bool clipPath(const Parcel& parcel, double dt, double mass, StepStatistics& stats,
                  ClippedPath& path) const;
    // Steps 3-6: the kernel's (or the cloud-in-cell) weights of the clipped path into sink.
    void weighPath(const Parcel& parcel, const ClippedPath& path, WeightSink& sink);
    // Distance from the path beyond which a node's weight is below
    // KernelSettings::negligibleWeight times the parcel's largest (<= reach).
    double negligibleDistance(const ParcelKernel& kernel, double pathLength) const;
    // Step 4: the lattice nodes within `reach` of the path (may be empty), ghost nodes
    // beyond the faces included (at most one grid length beyond each face).
    IndexBox nodeBox(const ClippedPath& path, double reach) const;
    // True when the box holds no ghost node (the kernel stays inside the grid).
    bool withinGrid(const IndexBox& box) const;
    // True when the box holds a node on a face of the grid box (active directions).
    bool touchesFace(const IndexBox& box) const;
    // Cloud-in-cell paths whose cells touch a face node: points faceRefinement times closer
    // (the midpoint rule's error along diagonal paths cancels between the cells around an
    // interior node, not at a face; docs/model.md sec. 4, edge nodes).
    static constexpr double faceRefinement = 8.0;
    // Step 4, exact code: omega of every lattice node of the box, batched (AVX2 + FMA,
    // moving parcels) or node by node; the nodes with omega > 0 go to scratch_ in node order,
    // ghost nodes folded onto their mirror images (weightedBox: the box of the listed
    // nodes). Returns sum omega over the lattice nodes.
    double weighLattice(const PathWeight& pathWeight, const ClippedPath& path, const IndexBox& box,
                        IndexBox& weightedBox);
    // Gauss-Legendre points for the separable weights of this parcel (SeparableWeight), 0
    // for the exact code: KernelSettings::method, a kernel reaching (cut-off included) at
    // least separableFromSpacings largest spacings, and SeparableWeight's bound with every
    // node of the box weighed (no threshold).
    int separablePoints(const PathWeight& pathWeight, std::size_t boxNodes) const;
    // Step 4 for wide kernels: SeparableWeight's tables (folded where the box has ghost
    // nodes; weightedBox: the folded box). Returns sum omega over the lattice box, from the
    // tables' per-axis sums (SeparableWeight::sum).
    double prepareSeparable(const PathWeight& pathWeight, const ClippedPath& path, const IndexBox& box,
                            int points, IndexBox& weightedBox);
    // Kernels reaching fewer spacings keep the exact code: at reach 1-2 spacings the
    // separable weights were 0.7-1.1x the exact code's speed (stationary; moving ones mostly
    // fail the bound: a path of h/2 is long against such a kernel), at 3.3 spacings 1.3-2.6x
    // (wideKernelBench).
    static constexpr double separableFromSpacings = 3.0;
    // Steps 5 and 7 for wide kernels: the (folded) box's omegas row by row times inverseSum
    // into the sink. Accumulating: only the rows of the box inside the storage box, straight
    // into the accumulator's contiguous values (evaluation and accumulation fused).
    void sendSeparable(double inverseSum, const IndexBox& box, WeightSink& sink);
    // Step 4 for wide kernels: the kept tables where the parcel has them (kept: a sparse
    // sink's find), prepareSeparable otherwise, keeping the tables (under key) where the
    // deposit is to (keepTablesNear). tables: those to weigh with; returns sum omega.
    double separableTables(const KeptTables::Key& key, const KeptTables::Entry* kept,
                           const PathWeight& pathWeight, const ClippedPath& path, const IndexBox& box,
                           int points, WeightSink& sink, IndexBox& weightedBox, SeparableTables& tables);
    // sendSeparable for a sparse sink: omega at the sink's nodes inside the box only.
    void shareSeparable(const SeparableTables& tables, double inverseSum, const IndexBox& box,
                        WeightSink& sink);
    // sendWeighted for a sparse sink: scratch_'s nodes merged with the sink's (node order).
    void shareWeighted(double inverseSum, WeightSink& sink);
    // The box's omegas (i fastest) -> scratch_ (omega > 0, node order; box inside the
    // grid). Returns their sum.
    double listWeighted(const double* boxOmega, const IndexBox& box);
    // Node by node, for boxes inside the grid (stationary parcels, small boxes, no AVX2).
    double weighNodesOneByOne(const PathWeight& pathWeight, const Eigen::Vector3d& start,
                              const IndexBox& box);
    // The nodes the lattice box's nodes fold onto (mirror images; the box itself when it
    // holds no ghost node).
    IndexBox foldedBox(const IndexBox& box) const;
    // omega of every lattice node of the box node by node (i fastest), valid until the next call.
    const double* latticeOmegas(const PathWeight& pathWeight, const Eigen::Vector3d& start,
                                const IndexBox& box);
    // The mirror images of the box's lattice indices per direction (mirrorImage_), and the
    // box of the nodes they name.
    IndexBox mirrorBox(const IndexBox& box);
    // Sums omega over the lattice box of mirrorBox and folds it onto foldedBox's nodes.
    double foldOntoNodes(const double* omega, const IndexBox& foldedBox);
    // Steps 5 and 7: scratch_'s nodes get omega / sum omega into the sink.
    void sendWeighted(double inverseSum, const IndexBox& box, WeightSink& sink);
    // Step 6 (and unresolved kernels): cloud-in-cell weights along the path into the sink.
    void weighCloudInCell(const Eigen::Vector3d& start, const Eigen::Vector3d& displacement,
                          WeightSink& sink);
    // The nodes weighCloudInCell weighs for this path.
    IndexBox cloudInCellBox(const Eigen::Vector3d& start, const Eigen::Vector3d& displacement) const;
    // One point's share on the corners of its cell (paths across many cells).
    void sendCorners(const Eigen::Vector3d& point, double share, WeightSink& sink);
    // The path's weights summed per node of its cell box (pathWeights_) into the sink.
    void sendPathWeights(const IndexBox& box, WeightSink& sink);
    // One node's weight into the sink.
    void send(WeightSink& sink, std::size_t node, double weight);
    // Rows ahead in sendSeparable whose accumulator values are prefetched (wideKernelBench,
    // 0.5 mm grid: 1 row 1.1-1.6x, 2 rows 1.2-2.1x faster than none; 4 rows within 5 % of 2).
    static constexpr std::size_t rowsAhead = 2;
    // Nodes ahead in sendWeighted's list whose accumulator values are prefetched.
    static constexpr std::size_t prefetchDistance = 32;
    // Step 7 for one node.
    void accumulate(std::size_t node, double weight, const std::array<double, nQuantities>& parcelTotals);
    // The step values of a node (global flat index); nullptr when not stored here.
    double* stepValuesOf(std::size_t node)
    {
        // Inline for the whole grid (a serial run): one call per weighted node
        return storesWholeGrid_ ? step_.data() + node * nQuantities : stepValuesOfBlockNode(node);
    }
    // A block's storage, or nullptr for nodes beyond it (other blocks deposit those).
    double* stepValuesOfBlockNode(std::size_t node);
    // restoreWindow() from a deposit log: its steps deposited again and committed.
    void replayLog(const WindowState& state);
    // Grid indices of a global flat node index.
    std::array<int, 3> nodeIndices(std::size_t node) const;
    // Where a touched box of nodes (grid indices) is stored: stepBox_ grows by it.
    void touch(const IndexBox& box) { stepBox_ = stepBox_.united(box.intersected(storage_)); }
    // The step array's lazy clearing (dirty_, rowPending_). A storage row's index: j + ny k
    // (storage indices).
    std::size_t storageRow(int j, int k) const
    {
        return static_cast<std::size_t>(j)
            + static_cast<std::size_t>(storage_.hi[1] - storage_.lo[1] + 1) * static_cast<std::size_t>(k);
    }
    // Zeroes the dirty part of a pending row (storageRow) and marks it cleared.
    void zeroPendingRow(std::size_t row) const;
    // Zeroes the pending rows that meet the box (grid indices): before writing into it.
    void clearPendingRowsOf(const IndexBox& box) const;
    // Zeroes every pending row: step_ then holds the step's values only.
    void clearPendingRows() const;
    // The evicted slot that became step_ holds its values in `dirty` (grid indices): every
    // row of it pending.
    void markDirty(const IndexBox& dirty);

    GridSpec spec_;
    KernelSettings kernelSettings_;
    int kernelDimension_;
    bool batched_;                                   // batchedKernel()
    std::array<std::vector<double>, 3> coordinates_; // lattice coordinates per direction (latticeCoordinates)
    std::array<int, 3> ghostLayers_{};               // ghost nodes beyond each face: nodes - 1 (flat: 0)
    std::array<double, 3> inverseSpacing_{};
    std::array<double, 3> spacing_{}; // 0 in flat directions
    double smallestSpacing_ = 0.0;    // over the active directions (cloud-in-cell path points)
    double largestSpacing_ = 0.0;     // over the active directions (KernelSettings::cloudInCellBelow)
    double halfCellDiagonal_ = 0.0;   // over the active directions (negligible weights)
    double nodeVolume_;               // of an interior node (whole cell)
    IndexBox owned_;                  // nodes owned: the window's region
    IndexBox storage_;                // nodes stored for the step's deposit
    bool storesWholeGrid_;            // storage_ is the whole grid: flat node index = storage index
    bool ownsWholeGrid_;              // owned_ is the whole grid: flat node index = window index
    AveragingWindow window_;
    DepositLog log_; // the parcels of the window's steps: its restart state
    // The step's accumulator (mutable: the lazy clearing below gives the same values, so
    // const readers may clear pending rows first).
    mutable std::vector<double> step_;
    IndexBox stepBox_;
    // commitStep() takes the evicted window slot as the next step_ without clearing it
    // (AveragingWindow::pushSwappingUncleared): clearing its box at the commit (about the
    // whole grid, 4.8 MB, in the spray3D case) brings every line of it into the caches,
    // and the next step's deposits bring them in again; a row zeroed just before a
    // deposit's first write into it is brought in once. dirty_ (storage indices) holds the
    // evicted step's values; rowPending_ (per storage row, storageRow) marks its rows whose
    // dirty part is not yet zeroed. Every write into step_ zeroes its row first
    // (sendSeparable row by row, the node-by-node paths over the rows of the parcel's box,
    // unpackStep over its box), every read of step_ too, and commitStep() the rows no
    // deposit reached: step_ holds to the bit what clearing the slot at once gave. Empty
    // (no pending row) for blocks whose storage is not the owned box (they copy the step
    // into the window).
    mutable IndexBox dirty_;
    mutable std::vector<unsigned char> rowPending_;
    StepStatistics stepStatistics_;
    StepStatistics copyStatistics_;
    StepStatistics lastStepStatistics_;
    std::vector<std::pair<std::size_t, double>> scratch_; // (node, omega) of the current parcel
    // Cloud-in-cell: weights of the current parcel's path summed per node of its box, for
    // boxes up to maximumPathBoxNodes (a 2D path across ~30 cells; longer ones go straight
    // onto the grid point by point)
    static constexpr std::size_t maximumPathBoxNodes = 1024;
    std::vector<double> pathWeights_;
    // Folded kernels: the current parcel's lattice omegas (node by node), the mirror image
    // of each lattice index per direction, and the omegas folded onto the nodes.
    std::vector<double> latticeOmega_;
    std::array<std::vector<int>, 3> mirrorImage_;
    std::vector<double> foldedOmega_;
    PathWeightBatch batch_;          // the batched deposit (batchedKernel(); unused, empty, otherwise)
    SeparableWeight separable_;      // wide kernels' per-axis tables
    KeptTables kept_;                // the tables kept for the removal (keepTablesNear)
    bool keptStepCommitted_ = false; // kept_ holds a committed step's: the next deposit forgets them
};

} // namespace dropletFiber
