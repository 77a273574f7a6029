#include "laydown/Footprint.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace dropletFiber
{

long MapLattice::columns() const
{
    return static_cast<long>(std::ceil((acrossMax - acrossMin) / cell - 1e-9));
}

long MapLattice::column(double across) const
{
    return static_cast<long>(std::floor((across - acrossMin) / cell));
}

long MapLattice::row(double along) const
{
    return static_cast<long>(std::floor(along / cell));
}

double MapLattice::columnWidth(long i) const
{
    return std::min(cell, acrossMax - (acrossMin + static_cast<double>(i) * cell));
}

double MapLattice::fold(double across) const
{
    if (across < acrossMin)
        across = 2.0 * acrossMin - across;
    else if (across > acrossMax)
        across = 2.0 * acrossMax - across;
    // Beyond a whole width (a hat or a line wider than the belt): at the edge
    return std::clamp(across, acrossMin, acrossMax);
}

double hatIntegral(double x, double h)
{
    const double u = x / h;
    if (u <= -1.0)
        return 0.0;
    if (u <= 0.0)
        return 0.5 * (1.0 + u) * (1.0 + u);
    if (u < 1.0)
        return 1.0 - 0.5 * (1.0 - u) * (1.0 - u);
    return 1.0;
}

namespace
{

using ShareMap = std::map<std::pair<long, long>, CellShare>;

// Half the end-to-end vector in the map's (across, along): along runs against e_a
// (Belt.hpp: along = V t - (foot - point).e_a)
Eigen::Vector2d halfSpan(const LaidFiber& fiber)
{
    return 0.5 * fiber.endToEnd * Eigen::Vector2d(fiber.orientation.x(), -fiber.orientation.y());
}

long clampedColumn(const MapLattice& lattice, double across)
{
    return std::clamp(lattice.column(lattice.fold(across)), 0L, lattice.columns() - 1);
}

// The parameters t in (0, 1) where x0 + t dx crosses one of the values start + k step.
void addCrossings(double x0, double dx, double start, double step, std::vector<double>& ts)
{
    if (dx == 0.0)
        return;
    const double lo = std::min(x0, x0 + dx), hi = std::max(x0, x0 + dx);
    const double kFrom = std::ceil((lo - start) / step), kTo = std::floor((hi - start) / step);
    for (double k = kFrom; k <= kTo; k += 1.0)
    {
        const double t = (start + k * step - x0) / dx;
        if (t > 0.0 && t < 1.0)
            ts.push_back(t);
    }
}

// The line: cut where it crosses an edge, a column's boundary (or its mirror in the far
// edge: the near edge's mirror of the lattice is the lattice) or a row's; each piece lies
// in one cell once folded.
void addLine(const LaidFiber& fiber, const MapLattice& lattice, ShareMap& shares)
{
    const Eigen::Vector2d d = halfSpan(fiber);
    const Eigen::Vector2d start = Eigen::Vector2d(fiber.across, fiber.along) - d;
    const Eigen::Vector2d delta = 2.0 * d;
    std::vector<double> ts{0.0, 1.0};
    const double h = lattice.cell;
    addCrossings(start.x(), delta.x(), lattice.acrossMin, h, ts);
    addCrossings(start.x(), delta.x(), 2.0 * lattice.acrossMax - lattice.acrossMin, h, ts);
    for (double edge : {lattice.acrossMin, lattice.acrossMax})
        if (delta.x() != 0.0)
            ts.push_back(std::clamp((edge - start.x()) / delta.x(), 0.0, 1.0));
    addCrossings(start.y(), delta.y(), 0.0, h, ts);
    std::sort(ts.begin(), ts.end());
    for (std::size_t k = 0; k + 1 < ts.size(); ++k)
    {
        const double piece = ts[k + 1] - ts[k];
        if (!(piece > 0.0))
            continue;
        const Eigen::Vector2d mid = start + 0.5 * (ts[k] + ts[k + 1]) * delta;
        const long column = clampedColumn(lattice, mid.x()), row = lattice.row(mid.y());
        CellShare& share = shares[{column, row}];
        share.column = column;
        share.row = row;
        share.line += piece;
    }
}

// The hat's share of each column across, folded at the edges; summing to 1.
std::vector<std::pair<long, double>> acrossHat(double x, double h, const MapLattice& lattice)
{
    const double left = lattice.acrossMin, right = lattice.acrossMax;
    // The columns the hat covers, with what it folds back over an edge
    const auto columnOf
        = [&lattice](double across) { return std::clamp(lattice.column(across), 0L, lattice.columns() - 1); };
    long lo = columnOf(x - h), hi = columnOf(x + h);
    if (x - h < left)
        hi = std::max(hi, columnOf(2.0 * left - x + h));
    if (x + h > right)
        lo = std::min(lo, columnOf(2.0 * right - x - h));
    std::vector<std::pair<long, double>> weights;
    double sum = 0.0;
    for (long i = lo; i <= hi; ++i)
    {
        const double a = left + static_cast<double>(i) * lattice.cell;
        const double b = a + lattice.columnWidth(i);
        const double w = hatIntegral(b - x, h) - hatIntegral(a - x, h) + hatIntegral(2.0 * left - a - x, h)
            - hatIntegral(2.0 * left - b - x, h) + hatIntegral(2.0 * right - a - x, h)
            - hatIntegral(2.0 * right - b - x, h);
        weights.emplace_back(i, w);
        sum += w;
    }
    for (auto& [i, w] : weights)
        w /= sum;
    return weights;
}

// The population: the hat of half-width `spread` around points along the line.
void addPopulation(const LaidFiber& fiber, const MapLattice& lattice, ShareMap& shares)
{
    const double H = fiber.spread;
    const Eigen::Vector2d d = halfSpan(fiber);
    const Eigen::Vector2d centre(fiber.across, fiber.along);
    const int points = std::max(1, static_cast<int>(std::ceil(8.0 * d.norm() / H)));
    for (int p = 0; p < points; ++p)
    {
        const double t = (p + 0.5) / points;
        const Eigen::Vector2d x = centre + (2.0 * t - 1.0) * d;
        const auto across = acrossHat(x.x(), H, lattice);
        for (long r = lattice.row(x.y() - H); r <= lattice.row(x.y() + H); ++r)
        {
            const double a = static_cast<double>(r) * lattice.cell;
            const double along = hatIntegral(a + lattice.cell - x.y(), H) - hatIntegral(a - x.y(), H);
            if (!(along > 0.0))
                continue;
            for (const auto& [column, w] : across)
            {
                CellShare& share = shares[{column, r}];
                share.column = column;
                share.row = r;
                share.population += w * along / points;
            }
        }
    }
}

} // namespace

LaidFiber wholeAtCentre(LaidFiber fiber)
{
    fiber.endToEnd = 0.0;
    fiber.spread = 0.0;
    return fiber;
}

std::vector<CellShare> footprint(const LaidFiber& fiber, const MapLattice& lattice)
{
    ShareMap shares;
    addLine(fiber, lattice, shares);
    if (fiber.spread > 0.0 && fiber.represents > 1.0)
        addPopulation(fiber, lattice, shares);
    std::vector<CellShare> out;
    out.reserve(shares.size());
    for (const auto& [key, share] : shares)
        out.push_back(share);
    return out;
}

} // namespace dropletFiber
