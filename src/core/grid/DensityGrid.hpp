// DensityGrid: droplet mass density, mean radius and mean velocity on a regular grid,
// from parcels (docs/model.md sec. 4, eqs. 19-26). Per time step:
//     for each parcel: deposit(parcel, dt)     -> the step's node values
//     commitStep()                              -> the step enters the averaging window
//     nodeValue(i, j, k), sample(point)         -> fields averaged over the window
//
// It composes the parts that each hold one idea, in the order a parcel meets them:
//   ParcelPath      steps 1-2: the parcel's checks, its path clipped to the grid box, and
//                   its quantities (eqs. 19, 25-26)
//   ParcelWeights   steps 3-6: the kernel and the weights of the parcel on the nodes
//                   (eqs. 12-24, P10, P16): exact (LatticeWeights), separable
//                   (SeparableWeight) or cloud-in-cell (CloudInCellWeights), folded at
//                   the faces (NodeLattice), handed to a WeightSink
//   StepValues      step 7: the weights times the parcel's quantities, added per node;
//                   the exchange of boxes between blocks
//   AveragingWindow the last W committed steps and their sums (eq. 26)
//   DepositLog      the parcels of the window's steps, its restart state
//   WindowSampler   the fields read from the window at a node or a point (sec. 5's input)
//   DepositedShare  depletion's sums of the deposit's weights times a fraction per node
//                   (sec. 7)
// DensityGrid itself keeps the step's statistics, the commit, and the window's save,
// restore and replay.
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
// commitStep(): the owned part of the step enters the window. With the whole grid as the
// block (the default) nothing changes.
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
// Memory: nQuantities = 7 doubles (56 bytes) per node for the step values (per stored
// node), the window total and each of the W window slots (allocated as the window fills;
// per owned node), and the window's 8-byte stamp: (W + 2) * 56 + 8 bytes per node for the
// whole grid, e.g. 250 x 250 nodes, W = 10: 43 MB; the arrays' pages are resident only
// where written (NodeValueArray). The deposit log: 72 bytes per parcel deposited on the
// grid in each of the W (+1) steps, e.g. 4,000 parcels per step, W = 10: 3.2 MB.
// Time per parcel: ~ nodes within reach of its path (one erf-type evaluation each, or a
// few multiplications with the separable tables).
#pragma once

#include "grid/AveragingWindow.hpp"
#include "grid/DepositLog.hpp"
#include "grid/DepositedShare.hpp"
#include "grid/GridQuantities.hpp"
#include "grid/GridSpec.hpp"
#include "grid/KeptTables.hpp"
#include "grid/MultilinearWeights.hpp"
#include "grid/Parcel.hpp"
#include "grid/ParcelKernel.hpp"
#include "grid/ParcelWeights.hpp"
#include "grid/SparseNodeValues.hpp"
#include "grid/StepStatistics.hpp"
#include "grid/StepValues.hpp"
#include "grid/WindowSampler.hpp"

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace dropletFiber
{

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
    const KernelSettings& kernelSettings() const { return weights_.kernelSettings(); }
    int kernelDimension() const { return weights_.kernelDimension(); } // 2 or 3, the r_min formula in use
    // True when deposit() evaluates moving parcels with the batched AVX2 + FMA node loop:
    // KernelSettings::vectorised and a CPU that has it (KernelBuild.hpp).
    bool batchedKernel() const { return weights_.batched(); }

    // --- one time step ---------------------------------------------------------------
    void deposit(const Parcel& parcel, double dt);
    // A parcel another block holds and deposits (see Blocks above): the same deposit onto
    // the nodes stored here, counted in copyStatistics() instead of stepStatistics().
    void depositCopy(const Parcel& parcel, double dt);
    // Ends the step: the step values enter the window and are cleared; statistics move
    // to lastStepStatistics().
    void commitStep();
    const StepStatistics& stepStatistics() const { return stepStatistics_; }
    const StepStatistics& lastStepStatistics() const { return lastStepStatistics_; }
    // What depositCopy() did this step (cleared by commitStep()).
    const StepStatistics& copyStatistics() const { return copyStatistics_; }

    // --- the deposit's weights re-evaluated (depletion, docs/model.md sec. 7) ------------
    using NodeFraction = dropletFiber::NodeFraction;
    using NodeBoxTest = dropletFiber::NodeBoxTest;
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
    // Visits those nodes only: separable weights evaluated per node (SeparableTables::omega),
    // the exact code's weighted nodes merged with them (both in node order), no per-node call.
    double depositedShare(const Parcel& parcel, double dt, const NodeBoxTest& asks,
                          const SparseNodeValues& fractions);
    // The same, and the parcel's weight w_n f at each of those nodes appended to weights
    // (their places in fractions.nodes(); the sum is sum over them of weight x value).
    double depositedShare(const Parcel& parcel, double dt, const NodeBoxTest& asks,
                          const SparseNodeValues& fractions, std::vector<NodeWeight>& weights);
    // The deposits from now on keep the separable tables of the parcels whose (folded)
    // weighted box meets `region` (grid indices; empty: none, the default), for the sparse
    // depositedShare of the same step (KeptTables.hpp). Only the time of depositedShare
    // depends on the region, never a result.
    void keepTablesNear(const IndexBox& region) { weights_.keptTables().setRegion(region); }
    // The tables the last step's deposits kept (their number and bytes).
    const KeptTables& keptTables() const { return weights_.keptTables(); }
    // A box (grid indices) holding every node deposit(parcel, dt) can give mass to: the
    // kernel's nodes (folded) and those of its cloud-in-cell fallback; empty when the
    // parcel gives the grid nothing. A parallel caller sends a parcel to the blocks whose
    // owned nodes this box meets (deposit), or whose nodes of interest
    // (CaptureLimit::takenBox) it meets (depletion).
    IndexBox depositBox(const Parcel& parcel, double dt) const;
    // Quantity q of the newest committed step at an owned node (global flat index): what
    // the step's parcels, summed over the blocks, deposited there; 0 before any commit.
    double lastStepValue(std::size_t node, int q) const { return sampler_.lastStepValue(window_, node, q); }

    // --- step values and the block's exchanges -------------------------------------------
    const IndexBox& ownedBox() const { return owned_; }
    const IndexBox& storageBox() const { return step_.storageBox(); }
    // storage.nodeCount() * nQuantities doubles, GridQuantities layout over the storage box
    // (flatIndexInBox; the whole grid: flat node index), zero outside stepBox(). The
    // vector's storage may change at commitStep() (it can become a window slot): take
    // data() anew after each commit. Writing through the non-const accessor (or
    // unpackStep) makes the step one that the deposit log cannot replay: saveWindow() then
    // saves node values until W deposited steps have followed.
    NodeValueArray& stepValues()
    {
        log_.markIncomplete();
        return step_.values();
    }
    const NodeValueArray& stepValues() const { return step_.values(); }
    // The stored nodes the step touched (grid indices).
    IndexBox stepBox() const { return step_.touchedBox(); }
    // Copies the box's values (nQuantities per node, i fastest; the box inside the storage
    // box) into a contiguous buffer...
    std::vector<double> packStep(const IndexBox& box) const;
    // The same into the caller's buffer of box.nodeCount() * nQuantities values (the
    // function object packs straight into its message).
    void packStep(const IndexBox& box, double* values) const { step_.pack(box, values); }
    // ...and back: overwrites the box (e.g. with the sum over ranks); stepBox() becomes
    // stepBox() united with box. Nodes outside the box are left as they are.
    void unpackStep(const IndexBox& box, const std::vector<double>& values)
    {
        unpackStep(box, values.data(), values.size());
    }
    void unpackStep(const IndexBox& box, const double* values, std::size_t count);

    // --- averaging window and fields ----------------------------------------------------
    int windowLength() const { return window_.length(); }
    int stepsInWindow() const { return window_.filled(); }
    std::int64_t committedSteps() const { return window_.committedSteps(); }
    // The window sums of the owned nodes, laid out over the owned box (flatIndexInBox).
    const NodeValueArray& windowTotals() const { return window_.total(); }
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
    // The node values of a part of the owned box (AveragingWindow::savePart): what moves
    // to another block when the blocks are re-partitioned.
    WindowState saveWindowPart(const IndexBox& part) const { return window_.savePart(part); }
    // Either format. A log is replayed: its parcels deposited again as copies, step by
    // step, oldest first, each step committed (the newest min(saved, W) steps): the same
    // slots and total bit for bit, given the same kernel settings, grid and code. A state
    // of a larger block (a serial run's whole grid) gives a block its part, as node values
    // do. Called before the step's deposits (throws std::invalid_argument otherwise, and
    // when the state does not fit this grid). The last step's statistics are kept.
    void restoreWindow(const WindowState& state);
    // The window's node values in its slots' boxes (what saveWindowValues() holds).
    std::size_t windowValueCount() const { return window_.savedValueCount(); }
    // restoreWindow(joinedWindowState(parts, ownedBox())) without the joined copy: the
    // parts' values copied into the window and each part freed once copied
    // (AveragingWindow::restoreParts): a re-partition's moved window.
    void restoreWindowParts(std::vector<WindowState>& parts)
    {
        window_.restoreParts(parts);
        log_.clear(); // node values: no log of these steps
    }
    // The window's pages wholly inside the rows of `box` given back (their values zero):
    // a grid that has saved that part of its window (saveWindowPart) and is to be freed,
    // at a re-partition, holds no second copy of it.
    void releaseWindowPages(const IndexBox& box) { window_.releasePages(box); }
    // The pages of the nodes of `box` (grid indices) resident in the step values, every
    // window slot and the total, no value changed: a block that takes nodes at a
    // re-partition faults in the spray's part of them at once (NodeValueArray.hpp).
    void makeResident(const IndexBox& box)
    {
        step_.makeResident(box);
        window_.makeResident(box);
    }
    // Parcels in the deposit log's committed steps.
    std::size_t loggedParcels() const { return log_.loggedParcels(); }

    // Fields at an owned node (grid indices / global flat index) (WindowSampler.hpp).
    DropletFieldValue nodeValue(int i, int j, int k) const { return nodeValue(spec_.flatIndex(i, j, k)); }
    DropletFieldValue nodeValue(std::size_t flatIndex) const
    {
        return sampler_.nodeValue(window_, flatIndex);
    }
    // nodeValue() from the node's window sums S_q (nQuantities values, wherever read).
    DropletFieldValue nodeValueFromTotals(std::size_t flatIndex, const double* sums) const
    {
        return sampler_.nodeValueFromTotals(window_, flatIndex, sums);
    }
    // The field at a point whose cell corners are owned here (all of them for the whole
    // grid); throws std::out_of_range otherwise.
    DropletFieldValue sample(const Eigen::Vector3d& point) const { return sampler_.sample(window_, point); }
    // The window sums S_q of an owned node (global flat index), nQuantities values.
    void windowTotal(std::size_t node, double* sums) const { sampler_.windowTotal(window_, node, sums); }
    bool owns(std::size_t node) const { return sampler_.owns(node); }
    // The sums sample() interpolates (per corner: weight x window sums per whole cell), over
    // the corners owned here only, added to `sums` in corner order. Summed over the blocks
    // that own a point's corners, they are sample()'s sums; fieldFromCornerSums() then gives
    // its value (the whole grid: the same arithmetic, in the same order, to the bit).
    void addOwnedCornerSums(const CornerWeights& corners, std::array<double, nQuantities>& sums) const
    {
        sampler_.addOwnedCornerSums(window_, corners, sums);
    }
    // Requests the memory addOwnedCornerSums(corners, ...) will read: called a few points
    // ahead, it overlaps their cache misses (AveragingWindow::prefetchNodeTotal).
    void prefetchOwnedCornerSums(const CornerWeights& corners) const
    {
        sampler_.prefetchOwnedCornerSums(window_, corners);
    }
    DropletFieldValue fieldFromCornerSums(const std::array<double, nQuantities>& sums) const
    {
        return sampler_.fieldFromSums(window_, sums);
    }
    // sample()'s value from the window sums of the corners (corner c's nQuantities values
    // at cornerTotals + c * nQuantities): the same arithmetic, in the same order.
    DropletFieldValue interpolated(const CornerWeights& corners, const double* cornerTotals) const
    {
        return sampler_.interpolated(window_, corners, cornerTotals);
    }
    // Each corner's part of the interpolated mass sum that gives sample()'s rho (the
    // corner weight times the corner's window mass per whole cell), into parts[c]; returns
    // their sum, rho times (node volume x steps in the window): the same arithmetic, in the
    // same order, as interpolated().
    double densityParts(const CornerWeights& corners, const double* cornerTotals, double* parts) const
    {
        return sampler_.densityParts(corners, cornerTotals, parts);
    }
    // Window mass per step on the owned nodes: sum over them of S_mass / s (kg).
    double windowMassPerStep() const { return sampler_.windowMassPerStep(window_); }

private:
    // depositedShare's steps: deposit()'s, the weights into the sink's sum (the part f of
    // the step inside the box times it; that part into *inside if given).
    template <class Sink>
    double shareOf(const Parcel& parcel, double dt, Sink& sink, double* inside = nullptr);
    // restoreWindow() from a deposit log: its steps deposited again and committed.
    void replayLog(const WindowState& state);

    GridSpec spec_;
    IndexBox owned_; // nodes owned: the window's region
    AveragingWindow window_;
    DepositLog log_; // the parcels of the window's steps: its restart state
    ParcelWeights weights_;
    StepValues step_;
    WindowSampler sampler_;
    StepStatistics stepStatistics_;
    StepStatistics copyStatistics_;
    StepStatistics lastStepStatistics_;
    bool keptStepCommitted_ = false; // the kept tables are a committed step's: the next deposit forgets them
};

} // namespace dropletFiber
