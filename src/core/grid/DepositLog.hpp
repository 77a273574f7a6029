// DepositLog: the parcels a DensityGrid deposited in each of the last W committed steps,
// in the order deposited, as the restart state of its averaging window.
//
// The window (eq. 26) is a deterministic function of those parcels: replaying them, step
// by step, oldest first (each parcel deposited again, in the same order, then the step
// committed) rebuilds every slot and the total bit for bit, with the same code, kernel
// settings and grid (DensityGrid::restoreWindow). So the state holds the parcels (9
// numbers each, ~72 bytes) instead of the slots' node values (56 bytes per node touched
// and step): on grids whose kernels touch most nodes, a few per cent of the size.
//
// Per step: the parcels' values in order (position xyz, velocity xyz, diameter,
// nParticle, rhoDroplet, as given to deposit() or depositCopy()), and the time steps they
// were deposited with as runs (dt, parcels). Only parcels that put mass on the grid are
// logged (one entirely outside the box, or empty, changes nothing). A step whose values
// did not all come from deposits (DensityGrid::unpackStep wrote into it) cannot be
// replayed: until W replayable steps have been committed after it, the grid saves the
// window's node values instead (complete() tells).
//
// Memory: W (+1, the step being deposited) step logs of 72 bytes per logged parcel; the
// buffers are reused from step to step (no allocation once the largest step was seen).
#pragma once

#include "grid/AveragingWindow.hpp"
#include "grid/GridSpec.hpp"
#include "grid/Parcel.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace dropletFiber
{

class DepositLog
{
public:
    // Numbers per logged parcel: position xyz, velocity xyz, diameter, nParticle, rhoDroplet.
    static constexpr std::size_t parcelValues = parcelValueCount;

    // One step's log, or a view of a saved one.
    struct StepView
    {
        const double* runs = nullptr; // (dt, parcel count) pairs
        std::size_t runCount = 0;
        const double* parcels = nullptr; // parcelValues per parcel
        std::size_t parcelCount = 0;
    };

    // The steps of a saved log (oldest first) and the window's counters, checked.
    struct Saved
    {
        int length = 0;             // the saving window's length
        std::int64_t committed = 0; // steps committed in total
        IndexBox region;            // the block of the grid the log covers (grid indices)
        std::vector<StepView> steps;
    };

    explicit DepositLog(int length);

    // The parcel the current step deposits (its values as deposited).
    void record(const Parcel& parcel, double dt);
    // The current step cannot be replayed (its values were written, not deposited).
    void markIncomplete() { currentComplete_ = false; }
    // The current step becomes the newest logged one; the oldest beyond W is dropped.
    void commit();
    // Drops every logged step (the window restored from node values, or about to be
    // rebuilt by a replay).
    void clear();
    // True when the newest `steps` committed steps are all logged and replayable.
    bool complete(int steps) const { return replayable_ >= steps; }
    // Parcels logged in the committed steps.
    std::size_t loggedParcels() const;

    // Restart state of a window of length `length` (filled steps, committed in total) over
    // region of a grid of gridNodes nodes, from the newest `filled` logged steps. Layout:
    //   counters = {format version 3 (the whole grid) or 4 (a block, its lo x y z hi x y z
    //               after the committed steps), nx, ny, nz, nQuantities, length, filled,
    //               committed, then per step, oldest first: parcels, runs}
    //   values   = per step, oldest first: runs x (dt, parcels), then parcels x 9 values.
    WindowState save(const std::array<int, 3>& gridNodes, const IndexBox& region, int nQuantities, int filled,
                     std::int64_t committed) const;
    // The number of values save() gives for the newest `filled` steps.
    std::size_t savedValueCount(int filled) const;
    // True when a saved state is a log (format 3 or 4), not node values (1 or 2).
    static bool holdsLog(const WindowState& state);
    // A saved log read and checked against a grid of gridNodes nodes whose window holds
    // `region`: the saved region must hold it (the same block, or the whole grid of a
    // serial run); counts, runs and every value (finite; dt, diameter, nParticle and
    // density >= 0). Throws std::invalid_argument naming what does not fit. The views point
    // into state.values.
    static Saved read(const WindowState& state, const std::array<int, 3>& gridNodes, const IndexBox& region,
                      int nQuantities);
    // The parcel at index p of a step view.
    static Parcel parcel(const StepView& step, std::size_t p);

private:
    struct Step
    {
        std::vector<double> parcels;
        std::vector<std::pair<double, std::size_t>> runs;
        void clear()
        {
            parcels.clear();
            runs.clear();
        }
    };
    // The step of age `age` (0: oldest logged).
    const Step& logged(int age) const
    {
        return steps_[static_cast<std::size_t>((head_ + age) % static_cast<int>(steps_.size()))];
    }

    std::vector<Step> steps_; // ring of W committed steps
    Step current_;
    int head_ = 0;       // oldest logged step
    int filled_ = 0;     // logged steps, <= W
    int replayable_ = 0; // newest committed steps that are replayable, <= W
    bool currentComplete_ = true;
};

} // namespace dropletFiber
