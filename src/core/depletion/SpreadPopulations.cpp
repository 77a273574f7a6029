// SpreadPopulations: a weighted fiber's population on its level (SpreadPopulations.hpp,
// docs/model.md sec. 12): the count, the level's choice, the demand terms, the reading of a
// level field.
#include "depletion/SpreadPopulations.hpp"
#include "depletion/SelfShadow.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dropletFiber
{

namespace
{
constexpr double pi = 3.14159265358979323846;
}

SpreadPopulations::SpreadPopulations(const GridSpec& grid, double neighbours, int maxRatio,
                                     double maxClustering)
    : grid_(grid), neighbours_(neighbours), maxClustering_(maxClustering)
{
    grid_.validate();
    if (!(neighbours > 0.0) || !std::isfinite(neighbours))
    {
        throw std::invalid_argument("spread populations: neighbours must be finite and > 0, not "
                                    + std::to_string(neighbours));
    }
    if (!(maxClustering >= 0.0) || !std::isfinite(maxClustering))
    {
        throw std::invalid_argument("spread populations: maxClustering must be finite and >= 0, not "
                                    + std::to_string(maxClustering));
    }
    const int largest = maxRatio > 0 ? maxRatio : defaultMaxRatio(grid_);
    for (const int ratio : spreadLevelRatios(largest))
    {
        if (static_cast<int>(levels_.size()) == maxLevels)
        {
            break;
        }
        levels_.emplace_back(grid_, ratio);
    }
}

int SpreadPopulations::defaultMaxRatio(const GridSpec& grid)
{
    double extent = 0.0;
    double spacing = 0.0;
    for (int d = 0; d < 3; ++d)
    {
        if (!grid.flat(d) && grid.upper[d] - grid.lower[d] > extent)
        {
            extent = grid.upper[d] - grid.lower[d];
            spacing = grid.spacing(d);
        }
    }
    const int reach = static_cast<int>(std::ceil(0.5 * extent / spacing - 1e-9));
    int ratio = 1;
    for (const int r : spreadLevelRatios(std::max(1, 2 * reach)))
    {
        ratio = r;
        if (r >= reach)
        {
            break;
        }
    }
    return ratio;
}

double SpreadPopulations::largestSpacing(const GridSpec& grid)
{
    double spacing = 0.0;
    for (int d = 0; d < 3; ++d)
    {
        spacing = grid.flat(d) ? spacing : std::max(spacing, grid.spacing(d));
    }
    return spacing;
}

void SpreadPopulations::addLength(const Eigen::Vector3d& centre, double length, LevelTerms& count) const
{
    for (int l = 0; l < levelCount(); ++l)
    {
        const CornerWeights w = level(l).weightsAt(centre);
        for (int c = 0; c < w.count; ++c)
        {
            const auto u = static_cast<std::size_t>(c);
            const double terms[2] = {length * w.weight[u], w.weight[u]};
            count.add(levelKey(l, w.node[u]), terms);
        }
    }
}

double SpreadPopulations::reachOn(int l, const Eigen::Vector3d& centre, double ownLength,
                                  const LevelTable& count) const
{
    const SpreadLevel& lvl = level(l);
    const CornerWeights w = lvl.weightsAt(centre);
    // lambda^ and n^ at the centre: the counts read per volume, the fiber's own out
    double lambda = 0.0, number = 0.0;
    for (int c = 0; c < w.count; ++c)
    {
        const auto u = static_cast<std::size_t>(c);
        const double* counted = count.find(levelKey(l, w.node[u]));
        const double length = counted ? counted[0] - ownLength * w.weight[u] : 0.0;
        const double fibers = counted ? counted[1] - (ownLength > 0.0 ? w.weight[u] : 0.0) : 0.0;
        lambda += w.weight[u] * std::max(0.0, length) / lvl.volume(w.node[u]);
        number += w.weight[u] * std::max(0.0, fibers) / lvl.volume(w.node[u]);
    }
    const double spacing = levelSpacing(l);
    // The fibers that meet a ball of radius sigma (Steiner: the ball grown by a segment of
    // length L has the volume 4/3 pi sigma^3 + pi sigma^2 L); on a grid with a flat
    // direction the fibers span it and a disc meets pi sigma^2 lambda of them
    const double sigma = spacing / std::sqrt(3.0);
    const double inside
        = grid_.activeDimensions() == 3 ? 4.0 / 3.0 * pi * sigma * sigma * sigma * number : 0.0;
    return pi * sigma * sigma * lambda + inside;
}

LevelChoice SpreadPopulations::choose(const Eigen::Vector3d& centre, double ownLength,
                                      const LevelTable& count, double opacity) const
{
    LevelChoice choice;
    for (int l = 0; l < levelCount(); ++l)
    {
        choice.level = l;
        choice.eps = opacity / levelSpacing(l);
        choice.reach = reachOn(l, centre, ownLength, count);
        if (maxClustering_ > 0.0 && choice.eps <= maxClustering_)
        {
            choice.why = LevelChoice::Why::thin;
            return choice;
        }
        if (choice.reach >= neighbours_)
        {
            choice.why = LevelChoice::Why::reached;
            return choice;
        }
    }
    choice.why = LevelChoice::Why::capped;
    return choice;
}

void SpreadPopulations::addDemand(const Eigen::Vector3d& point, int level, double volume,
                                  const Eigen::Vector3d& strip, double fibers, LevelTerms& demand) const
{
    const SpreadLevel& lvl = this->level(level);
    const CornerWeights w = lvl.weightsAt(point);
    // P54: the population's strip (N + 1) q_d on its level, shadowing itself and its line
    const std::array<double, 8> sigma = selfShadow(lvl.spec(), w, (fibers + 1.0) * strip);
    for (int c = 0; c < w.count; ++c)
    {
        const auto u = static_cast<std::size_t>(c);
        const double part = volume * w.weight[u];
        const double terms[2] = {part, part * (1.0 + sigma[u])};
        demand.add(levelKey(level, w.node[u]), terms);
    }
}

void SpreadPopulations::addAtLevel(const Eigen::Vector3d& point, int level, double amount,
                                   LevelTerms& terms) const
{
    const CornerWeights w = this->level(level).weightsAt(point);
    for (int c = 0; c < w.count; ++c)
    {
        const auto u = static_cast<std::size_t>(c);
        terms.add(levelKey(level, w.node[u]), amount * w.weight[u]);
    }
}

IndexBox SpreadPopulations::reach(const LevelTable& table) const
{
    IndexBox box;
    for (const LevelKey key : table.keys)
    {
        box = box.united(level(levelOfKey(key)).hatBox(nodeOfKey(key)));
    }
    return box;
}

void SpreadPopulations::prolongOnto(const LevelTable& table, const IndexBox& region,
                                    std::vector<double>& share, std::vector<double>& depth) const
{
    const std::size_t count = region.empty() ? 0 : region.nodeCount();
    const bool withDepth = table.width > 1;
    share.assign(count, 0.0);
    depth.assign(withDepth ? count : 0, 0.0);
    const auto w = static_cast<std::size_t>(table.width);
    for (std::size_t i = 0; i < table.keys.size() && count > 0; ++i)
    {
        const SpreadLevel& lvl = level(levelOfKey(table.keys[i]));
        const std::size_t coarse = nodeOfKey(table.keys[i]);
        const double volume = lvl.volume(coarse);
        const double s = table.values[w * i] / volume;
        const double x = withDepth ? table.values[w * i + 1] / volume : 0.0;
        lvl.forEachFineNodeIn(coarse, region,
                              [&](std::size_t at, double hat)
                              {
                                  share[at] += hat * s;
                                  if (withDepth)
                                  {
                                      depth[at] += hat * x;
                                  }
                              });
    }
}

LevelTable SpreadPopulations::restrictFrom(const LevelTable& keys, const IndexBox& region,
                                           const std::vector<double>& values) const
{
    LevelTable table;
    table.width = 1;
    table.keys = keys.keys;
    table.values.assign(keys.keys.size(), 0.0);
    for (std::size_t i = 0; i < keys.keys.size() && !region.empty(); ++i)
    {
        double sum = 0.0;
        level(levelOfKey(keys.keys[i]))
            .forEachFineNodeIn(nodeOfKey(keys.keys[i]), region,
                               [&](std::size_t at, double hat) { sum += hat * values[at]; });
        table.values[i] = sum;
    }
    return table;
}

double SpreadPopulations::readLevel(const Eigen::Vector3d& point, int level, const LevelTable& table,
                                    int column) const
{
    const SpreadLevel& lvl = this->level(level);
    const CornerWeights w = lvl.weightsAt(point);
    double sum = 0.0;
    for (int c = 0; c < w.count; ++c)
    {
        const auto u = static_cast<std::size_t>(c);
        sum += w.weight[u] * table.value(levelKey(level, w.node[u]), column) / lvl.volume(w.node[u]);
    }
    return sum;
}

} // namespace dropletFiber
