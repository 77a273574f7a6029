// SpreadLevel: the coarser lattice of a spread population (SpreadLevel.hpp, docs/model.md
// sec. 12, P53): its nodes, hats, volumes, restriction and prolongation.
#include "grid/SpreadLevel.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace dropletFiber
{

std::vector<int> spreadLevelRatios(int maxRatio)
{
    if (maxRatio < 1)
    {
        throw std::invalid_argument("spread level ratios: the largest ratio must be >= 1, not "
                                    + std::to_string(maxRatio));
    }
    std::vector<int> ratios{1};
    // 2^j and 3 2^j in increasing order: 2, 3, 4, 6, 8, 12, ...
    for (long power = 2; power <= maxRatio; power *= 2)
    {
        ratios.push_back(static_cast<int>(power));
        const long between = 3 * power / 2;
        if (between <= maxRatio)
        {
            ratios.push_back(static_cast<int>(between));
        }
    }
    return ratios;
}

SpreadLevel::SpreadLevel(const GridSpec& grid, int ratio) : grid_(grid), level_(grid), ratio_(ratio)
{
    grid_.validate();
    if (ratio < 1)
    {
        throw std::invalid_argument(
            "spread level: the ratio of its spacing to the grid's must be an integer >= 1, not "
            + std::to_string(ratio));
    }
    for (int d = 0; d < 3; ++d)
    {
        if (grid_.flat(d))
        {
            continue;
        }
        const int cells = grid_.nodes[d] - 1;
        const int levelCells = (cells + ratio - 1) / ratio;
        level_.nodes[d] = levelCells + 1;
        level_.upper[d] = grid_.lower[d] + levelCells * (ratio * grid_.spacing(d));
    }
    for (int d = 0; d < 3; ++d)
    {
        std::vector<double>& axis = axisVolume_[static_cast<std::size_t>(d)];
        axis.assign(static_cast<std::size_t>(level_.nodes[d]), 0.0);
        if (grid_.flat(d))
        {
            axis[0] = grid_.spacing(d);
            continue;
        }
        const int last = grid_.nodes[d] - 1;
        for (int fine = 0; fine <= last; ++fine)
        {
            const double width = (fine == 0 || fine == last ? 0.5 : 1.0) * grid_.spacing(d);
            const AxisShare s = share(d, fine);
            for (int a = 0; a < s.count; ++a)
            {
                axis[static_cast<std::size_t>(s.coarse[static_cast<std::size_t>(a)])]
                    += s.hat[static_cast<std::size_t>(a)] * width;
            }
        }
    }
}

IndexBox SpreadLevel::hatBox(std::size_t levelNode) const
{
    const std::array<int, 3> c = nodeIndicesOfFlat(level_.nodes, levelNode);
    IndexBox box;
    for (int d = 0; d < 3; ++d)
    {
        const auto u = static_cast<std::size_t>(d);
        box.lo[u] = grid_.flat(d) ? 0 : std::max(0, ratio_ * (c[u] - 1) + 1);
        box.hi[u] = grid_.flat(d) ? 0 : std::min(grid_.nodes[d] - 1, ratio_ * (c[u] + 1) - 1);
    }
    return box;
}

double SpreadLevel::volume(std::size_t levelNode) const
{
    const std::array<int, 3> c = nodeIndicesOfFlat(level_.nodes, levelNode);
    return axisVolume_[0][static_cast<std::size_t>(c[0])] * axisVolume_[1][static_cast<std::size_t>(c[1])]
        * axisVolume_[2][static_cast<std::size_t>(c[2])];
}

std::vector<double> SpreadLevel::volumes() const
{
    std::vector<double> v(level_.nodeCount());
    for (std::size_t c = 0; c < v.size(); ++c)
    {
        v[c] = volume(c);
    }
    return v;
}

double SpreadLevel::hat(int d, int coarse, int fine) const
{
    if (grid_.flat(d))
    {
        return 1.0;
    }
    const double distance = std::abs(static_cast<double>(fine - ratio_ * coarse)) / ratio_;
    return distance < 1.0 ? 1.0 - distance : 0.0;
}

SpreadLevel::AxisShare SpreadLevel::share(int d, int fine) const
{
    AxisShare s;
    if (grid_.flat(d))
    {
        return s;
    }
    const int lowerNode = fine / ratio_;
    const int offset = fine - lowerNode * ratio_;
    s.coarse = {{lowerNode, lowerNode + 1}};
    s.hat = {{hat(d, lowerNode, fine), hat(d, lowerNode + 1, fine)}};
    s.count = offset == 0 ? 1 : 2;
    return s;
}

template <class F>
void SpreadLevel::forEachPair(F&& f) const
{
    for (int k = 0; k < grid_.nodes[2]; ++k)
    {
        const AxisShare sk = share(2, k);
        for (int j = 0; j < grid_.nodes[1]; ++j)
        {
            const AxisShare sj = share(1, j);
            for (int i = 0; i < grid_.nodes[0]; ++i)
            {
                const AxisShare si = share(0, i);
                const std::size_t fine = grid_.flatIndex(i, j, k);
                for (int c = 0; c < sk.count; ++c)
                {
                    for (int b = 0; b < sj.count; ++b)
                    {
                        for (int a = 0; a < si.count; ++a)
                        {
                            f(fine, level_.flatIndex(si.coarse[a], sj.coarse[b], sk.coarse[c]),
                              si.hat[a] * sj.hat[b] * sk.hat[c]);
                        }
                    }
                }
            }
        }
    }
}

std::vector<double> SpreadLevel::restrict(const std::vector<double>& fine) const
{
    if (fine.size() != grid_.nodeCount())
    {
        throw std::invalid_argument("spread level: restrict takes one value per grid node ("
                                    + std::to_string(grid_.nodeCount()) + "), not "
                                    + std::to_string(fine.size()));
    }
    std::vector<double> coarse(level_.nodeCount(), 0.0);
    forEachPair([&](std::size_t n, std::size_t c, double w) { coarse[c] += w * fine[n]; });
    return coarse;
}

std::vector<double> SpreadLevel::prolong(const std::vector<double>& coarse) const
{
    if (coarse.size() != level_.nodeCount())
    {
        throw std::invalid_argument("spread level: prolong takes one value per level node ("
                                    + std::to_string(level_.nodeCount()) + "), not "
                                    + std::to_string(coarse.size()));
    }
    std::vector<double> fine(grid_.nodeCount(), 0.0);
    forEachPair([&](std::size_t n, std::size_t c, double w) { fine[n] += w * coarse[c]; });
    return fine;
}

CornerWeights SpreadLevel::weightsAt(const Eigen::Vector3d& point) const
{
    return multilinearWeights(level_, point);
}

} // namespace dropletFiber
