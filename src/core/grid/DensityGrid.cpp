#include "grid/DensityGrid.hpp"

#include "grid/ParcelPath.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace dropletFiber
{

namespace
{

const GridSpec& validated(const GridSpec& spec)
{
    spec.validate();
    return spec;
}

GridBlock checkedBlock(const GridSpec& spec, const GridBlock& block)
{
    spec.validate();
    const IndexBox grid = spec.fullBox();
    if (block.owned.empty() || block.storage.intersected(grid) != block.storage
        || block.owned.intersected(block.storage) != block.owned)
    {
        throw std::invalid_argument(
            "DensityGrid: a block's owned nodes must be a non-empty box inside its storage "
            "box, inside the grid");
    }
    return block;
}

} // namespace

DensityGrid::DensityGrid(const GridSpec& spec, const KernelSettings& kernel, int windowLength)
    : DensityGrid(spec, kernel, windowLength, GridBlock{validated(spec).fullBox(), spec.fullBox()})
{
}

DensityGrid::DensityGrid(const GridSpec& spec, const KernelSettings& kernel, int windowLength,
                         const GridBlock& block)
    : spec_(validated(spec)), owned_(checkedBlock(spec, block).owned),
      window_(spec.nodes, block.owned, nQuantities, windowLength), log_(windowLength), weights_(spec, kernel),
      step_(spec.nodes, block.storage), sampler_(spec, block.owned)
{
}

void DensityGrid::deposit(const Parcel& parcel, double dt)
{
    checkParcel(parcel, dt);
    if (keptStepCommitted_)
    {
        // A new step: the last one's kept tables are no longer asked for
        weights_.keptTables().clear();
        keptStepCommitted_ = false;
    }
    StepStatistics& stats = stepStatistics_;
    ++stats.parcels;
    if (emptyParcel(parcel))
    {
        ++stats.parcelsEmpty;
        return;
    }
    const double mass = parcelMass(parcel);
    stats.massIn += mass;

    // 1-2. Path during the step, clipped to the grid box.
    ClippedPath path;
    if (!clipPath(spec_, parcel, dt, mass, stats, path))
    {
        return;
    }
    // The window's restart state: what is deposited, as given (depletion changes the
    // parcel's nParticle after this)
    log_.record(parcel, dt);
    // 3-7. The weights of the nodes, onto the step values.
    const ParcelTotals totals = parcelTotals(parcel, mass, path.fraction);
    StepDeposit sink(step_, totals, weights_.batched(), stats);
    weights_.weigh(parcel, path, sink);
}

void DensityGrid::depositCopy(const Parcel& parcel, double dt)
{
    // deposit() books into stepStatistics_: swapped, so that it books into the copies'
    // statistics and the parcel's mass is counted once, by the block that holds it
    std::swap(stepStatistics_, copyStatistics_);
    try
    {
        deposit(parcel, dt);
    }
    catch (...)
    {
        std::swap(stepStatistics_, copyStatistics_);
        throw;
    }
    std::swap(stepStatistics_, copyStatistics_);
}

double DensityGrid::depositedShare(const Parcel& parcel, double dt, const NodeBoxTest& asks,
                                   const NodeFraction& fraction, const IndexBox& region)
{
    StepStatistics unused;
    FractionSum sink(unused, asks, fraction, region, spec_.nodes);
    return shareOf(parcel, dt, sink);
}

double DensityGrid::depositedShare(const Parcel& parcel, double dt, const NodeBoxTest& asks,
                                   const SparseNodeValues& fractions)
{
    StepStatistics unused;
    SparseFractionSum sink(unused, asks, fractions, spec_.nodes);
    return shareOf(parcel, dt, sink);
}

double DensityGrid::depositedShare(const Parcel& parcel, double dt, const NodeBoxTest& asks,
                                   const SparseNodeValues& fractions, std::vector<NodeWeight>& weights)
{
    StepStatistics unused;
    SparseFractionSum sink(unused, asks, fractions, spec_.nodes);
    const std::size_t first = weights.size();
    sink.keepWeights(&weights);
    double inside = 0.0;
    const double share = shareOf(parcel, dt, sink, &inside);
    // The weights as the sum has them, times the part of the step inside the box
    for (std::size_t i = first; i < weights.size(); ++i)
    {
        weights[i].weight *= inside;
    }
    return share;
}

template <class Sink>
double DensityGrid::shareOf(const Parcel& parcel, double dt, Sink& sink, double* inside)
{
    checkParcel(parcel, dt);
    if (emptyParcel(parcel))
    {
        return 0.0;
    }
    // deposit()'s steps on their own statistics, the weights into the sum.
    ClippedPath path;
    if (!clipPath(spec_, parcel, dt, parcelMass(parcel), sink.statistics(), path))
    {
        return 0.0;
    }
    weights_.weigh(parcel, path, sink);
    if (inside != nullptr)
    {
        *inside = path.fraction;
    }
    return path.fraction * sink.sum();
}

IndexBox DensityGrid::depositBox(const Parcel& parcel, double dt) const
{
    checkParcel(parcel, dt);
    StepStatistics unused;
    ClippedPath path;
    if (emptyParcel(parcel) || !clipPath(spec_, parcel, dt, parcelMass(parcel), unused, path))
    {
        return IndexBox{};
    }
    return weights_.box(parcel, path);
}

void DensityGrid::commitStep()
{
    step_.commitTo(window_, owned_);
    lastStepStatistics_ = stepStatistics_;
    stepStatistics_ = StepStatistics{};
    copyStatistics_ = StepStatistics{};
    log_.commit();
    keptStepCommitted_ = true; // the kept tables stay for this step's removal
}

std::vector<double> DensityGrid::packStep(const IndexBox& box) const
{
    std::vector<double> values(box.empty() ? 0 : box.nodeCount() * nQuantities);
    packStep(box, values.data());
    return values;
}

void DensityGrid::unpackStep(const IndexBox& box, const double* values, std::size_t count)
{
    if (box.empty())
    {
        return;
    }
    step_.unpack(box, values, count);
    log_.markIncomplete(); // values that no logged deposit gives
}

WindowState DensityGrid::saveWindow(WindowStateFormat format) const
{
    const int filled = window_.filled();
    // Node values where a step was not deposited (unpackStep), or restored from node values
    const bool log = log_.complete(filled)
        && (format == WindowStateFormat::DepositLog
            || (format == WindowStateFormat::Smaller
                && log_.savedValueCount(filled) <= window_.savedValueCount()));
    return log ? log_.save(spec_.nodes, owned_, nQuantities, filled, window_.committedSteps())
               : window_.save();
}

void DensityGrid::restoreWindow(const WindowState& state)
{
    if (DepositLog::holdsLog(state))
    {
        replayLog(state);
        return;
    }
    window_.restore(state);
    log_.clear(); // node values: no log of these steps
}

void DensityGrid::replayLog(const WindowState& state)
{
    // Everything checked before this grid changes
    const DepositLog::Saved saved = DepositLog::read(state, spec_.nodes, owned_, nQuantities);
    if (!step_.touchedBox().empty() || stepStatistics_.parcels != 0 || copyStatistics_.parcels != 0)
    {
        throw std::invalid_argument(
            "DensityGrid::restoreWindow: the step has deposits (restore before them)");
    }
    // The newest min(saved, W) steps, oldest first
    const std::size_t kept = std::min(saved.steps.size(), static_cast<std::size_t>(window_.length()));
    const bool sameRegion = saved.region == owned_;
    const StepStatistics last = lastStepStatistics_;
    log_.clear();
    window_.clear(saved.committed - static_cast<std::int64_t>(kept));
    for (std::size_t s = saved.steps.size() - kept; s < saved.steps.size(); ++s)
    {
        const DepositLog::StepView& step = saved.steps[s];
        std::size_t p = 0;
        for (std::size_t r = 0; r < step.runCount; ++r)
        {
            const double dt = step.runs[2 * r];
            const std::size_t end = p + static_cast<std::size_t>(step.runs[2 * r + 1]);
            for (; p < end; ++p)
            {
                const Parcel parcel = DepositLog::parcel(step, p);
                // A larger region's log (a serial run's, decomposed): the parcels that reach
                // none of the nodes stored here add nothing, and are not logged again
                if (sameRegion || !depositBox(parcel, dt).intersected(step_.storageBox()).empty())
                {
                    depositCopy(parcel, dt);
                }
            }
        }
        commitStep();
    }
    lastStepStatistics_ = last;
}

} // namespace dropletFiber
