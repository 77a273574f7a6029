#include "grid/DepositLog.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace dropletFiber
{

namespace
{
constexpr std::int64_t formatVersion = 3;      // the whole grid
constexpr std::int64_t blockFormatVersion = 4; // a block of it: its box after the header
constexpr const char* parcelValueNames[DepositLog::parcelValues]
    = {"position x", "position y", "position z", "velocity x", "velocity y",
       "velocity z", "diameter",   "nParticle",  "rhoDroplet"};

[[noreturn]] void failRestart(const std::string& what)
{
    throw std::invalid_argument("averaging window restart (deposit log): " + what);
}

std::string valueText(double v)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

// "value N (step s of S, what) is v: allowed are ..."
[[noreturn]] void failValue(std::size_t index, std::size_t step, std::size_t steps, const std::string& what,
                            double value, const std::string& allowed)
{
    failRestart("value " + std::to_string(index) + " (step " + std::to_string(step + 1) + " of "
                + std::to_string(steps) + ", " + what + ") is " + valueText(value) + ": allowed are "
                + allowed);
}
} // namespace

DepositLog::DepositLog(int length)
{
    if (length < 1)
    {
        throw std::invalid_argument("deposit log: length must be at least 1 step, got "
                                    + std::to_string(length));
    }
    steps_.resize(static_cast<std::size_t>(length));
}

void DepositLog::record(const Parcel& parcel, double dt)
{
    // A run per time step: one in a solver's step (every parcel with the step's dt)
    if (current_.runs.empty() || current_.runs.back().first != dt)
    {
        current_.runs.emplace_back(dt, 0);
    }
    ++current_.runs.back().second;
    const std::size_t end = current_.parcels.size();
    current_.parcels.resize(end + parcelValues);
    writeParcelValues(parcel, current_.parcels.data() + end);
}

void DepositLog::commit()
{
    const int length = static_cast<int>(steps_.size());
    // The slot of the oldest step when full, else the next free one; its buffers are reused
    const int slot = filled_ == length ? head_ : (head_ + filled_) % length;
    std::swap(steps_[static_cast<std::size_t>(slot)], current_);
    current_.clear();
    if (filled_ == length)
    {
        head_ = (head_ + 1) % length;
    }
    else
    {
        ++filled_;
    }
    replayable_ = currentComplete_ ? std::min(replayable_ + 1, length) : 0;
    currentComplete_ = true;
}

void DepositLog::clear()
{
    for (Step& step : steps_)
    {
        step.clear();
    }
    current_.clear();
    head_ = 0;
    filled_ = 0;
    replayable_ = 0;
    currentComplete_ = true;
}

std::size_t DepositLog::loggedParcels() const
{
    std::size_t parcels = 0;
    for (int age = 0; age < filled_; ++age)
    {
        parcels += logged(age).parcels.size() / parcelValues;
    }
    return parcels;
}

std::size_t DepositLog::savedValueCount(int filled) const
{
    std::size_t count = 0;
    for (int age = std::max(filled_ - filled, 0); age < filled_; ++age)
    {
        count += logged(age).parcels.size() + 2 * logged(age).runs.size();
    }
    return count;
}

WindowState DepositLog::save(const std::array<int, 3>& gridNodes, const IndexBox& region, int nQuantities,
                             int filled, std::int64_t committed) const
{
    if (!complete(filled) || filled > filled_)
    {
        throw std::logic_error("deposit log: the window's steps are not all logged");
    }
    IndexBox whole;
    whole.lo = {{0, 0, 0}};
    whole.hi = {{gridNodes[0] - 1, gridNodes[1] - 1, gridNodes[2] - 1}};
    const bool block = region != whole;
    WindowState state;
    state.counters
        = {block ? blockFormatVersion : formatVersion, gridNodes[0], gridNodes[1], gridNodes[2], nQuantities,
           static_cast<std::int64_t>(steps_.size()),   filled,       committed};
    if (block)
    {
        state.counters.insert(
            state.counters.end(),
            {region.lo[0], region.lo[1], region.lo[2], region.hi[0], region.hi[1], region.hi[2]});
    }
    state.values.reserve(savedValueCount(filled));
    for (int age = filled_ - filled; age < filled_; ++age)
    {
        const Step& step = logged(age);
        state.counters.push_back(static_cast<std::int64_t>(step.parcels.size() / parcelValues));
        state.counters.push_back(static_cast<std::int64_t>(step.runs.size()));
        for (const auto& run : step.runs)
        {
            state.values.push_back(run.first);
            state.values.push_back(static_cast<double>(run.second));
        }
        state.values.insert(state.values.end(), step.parcels.begin(), step.parcels.end());
    }
    return state;
}

bool DepositLog::holdsLog(const WindowState& state)
{
    return !state.counters.empty()
        && (state.counters[0] == formatVersion || state.counters[0] == blockFormatVersion);
}

namespace
{
// One step's runs and parcels checked: counts, and every value allowed.
void checkStep(const DepositLog::StepView& step, std::size_t first, std::size_t s, std::size_t steps)
{
    std::size_t inRuns = 0;
    for (std::size_t r = 0; r < step.runCount; ++r)
    {
        const double dt = step.runs[2 * r];
        const double count = step.runs[2 * r + 1];
        if (!std::isfinite(dt) || dt < 0.0)
        {
            failValue(first + 2 * r, s, steps, "the time step of run " + std::to_string(r + 1), dt,
                      "finite values >= 0");
        }
        if (!(count >= 0.0) || count != std::floor(count) || count > 1e15)
        {
            failValue(first + 2 * r + 1, s, steps, "the parcel count of run " + std::to_string(r + 1), count,
                      "counts");
        }
        inRuns += static_cast<std::size_t>(count);
    }
    if (inRuns != step.parcelCount)
    {
        failRestart("step " + std::to_string(s + 1) + " of " + std::to_string(steps) + ": its runs hold "
                    + std::to_string(inRuns) + " parcels, its counter says "
                    + std::to_string(step.parcelCount));
    }
    const std::size_t start = first + 2 * step.runCount;
    for (std::size_t n = 0; n < step.parcelCount * DepositLog::parcelValues; ++n)
    {
        const double v = step.parcels[n];
        const std::size_t field = n % DepositLog::parcelValues;
        const bool mayBeNegative = field < 6; // position, velocity
        if (!std::isfinite(v) || (!mayBeNegative && v < 0.0))
        {
            failValue(start + n, s, steps,
                      "parcel " + std::to_string(n / DepositLog::parcelValues + 1) + ", "
                          + parcelValueNames[field],
                      v, mayBeNegative ? "finite values" : "finite values >= 0");
        }
    }
}
} // namespace

DepositLog::Saved DepositLog::read(const WindowState& state, const std::array<int, 3>& gridNodes,
                                   const IndexBox& region, int nQuantities)
{
    const std::vector<std::int64_t>& c = state.counters;
    Saved saved;
    const std::size_t header
        = readWindowStateHeader(c, formatVersion, blockFormatVersion, gridNodes, nQuantities, region,
                                "averaging window restart (deposit log)", saved.region);
    const std::int64_t steps = c[6];
    if (c[5] < 1 || steps < 0 || steps > c[5] || c[7] < steps
        || c.size() != header + 2 * static_cast<std::size_t>(steps))
    {
        failRestart("inconsistent step count");
    }
    saved.length = static_cast<int>(c[5]);
    saved.committed = c[7];
    // Every count checked before any value is addressed through it
    std::size_t expected = 0;
    for (std::size_t s = 0; s < static_cast<std::size_t>(steps); ++s)
    {
        const std::int64_t parcels = c[header + 2 * s];
        const std::int64_t runs = c[header + 2 * s + 1];
        if (parcels < 0 || runs < 0 || parcels > std::int64_t(1e15) || runs > parcels)
        {
            failRestart("inconsistent parcel or run count of step " + std::to_string(s + 1));
        }
        expected += 2 * static_cast<std::size_t>(runs) + parcelValues * static_cast<std::size_t>(parcels);
    }
    if (expected != state.values.size())
    {
        failRestart("value count " + std::to_string(state.values.size()) + " does not match the steps' "
                    + std::to_string(expected));
    }
    std::size_t position = 0;
    for (std::size_t s = 0; s < static_cast<std::size_t>(steps); ++s)
    {
        StepView step;
        step.parcelCount = static_cast<std::size_t>(c[header + 2 * s]);
        step.runCount = static_cast<std::size_t>(c[header + 2 * s + 1]);
        step.runs = state.values.data() + position;
        step.parcels = step.runs + 2 * step.runCount;
        checkStep(step, position, s, static_cast<std::size_t>(steps));
        position += 2 * step.runCount + parcelValues * step.parcelCount;
        saved.steps.push_back(step);
    }
    return saved;
}

Parcel DepositLog::parcel(const StepView& step, std::size_t p)
{
    return parcelFromValues(step.parcels + p * parcelValues);
}

} // namespace dropletFiber
