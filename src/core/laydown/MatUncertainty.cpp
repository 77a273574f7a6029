#include "laydown/MatUncertainty.hpp"

#include <cmath>

namespace dropletFiber
{

ValueWithError lossOnIgnition(double glass, double binder, double varGlass, double varBinder,
                              double covariance)
{
    const double sum = glass + binder;
    if (!(sum > 0.0))
        return {};
    // dL/db = g / s^2, dL/dg = -b / s^2
    const double var
        = (glass * glass * varBinder + binder * binder * varGlass - 2.0 * glass * binder * covariance)
        / (sum * sum * sum * sum);
    return {binder / sum, std::sqrt(std::max(var, 0.0))};
}

ValueWithError cellAreaWeight(const MatCell& cell, double area)
{
    return {cell.glass / area, std::sqrt(cell.glassSquares) / area};
}

ValueWithError cellLoi(const MatCell& cell)
{
    return lossOnIgnition(cell.glass, cell.binder, cell.glassSquares, cell.binderSquares, cell.glassBinder);
}

AcrossProfile acrossProfileWithErrors(const MatMap& map, long rowFrom, long rowTo)
{
    const MapLattice& lattice = map.lattice();
    const long columns = lattice.columns();
    const auto n = static_cast<std::size_t>(std::max(columns, 0L));
    AcrossProfile profile;
    profile.areaWeight.resize(n);
    profile.loi.resize(n);
    const long rows = rowTo - rowFrom + 1;
    if (rows <= 0 || n == 0)
        return profile;
    std::vector<MatCell> column(n);
    double meanArea = 0.0;
    for (long i = 0; i < columns; ++i)
        meanArea
            += lattice.columnWidth(i) * lattice.cell * static_cast<double>(rows) / static_cast<double>(n);
    double total = 0.0;
    MatCell all;
    for (const auto& [key, c] : map.cells())
    {
        const auto [i, j] = key;
        if (i < 0 || i >= columns || j < rowFrom || j > rowTo)
            continue;
        MatCell& s = column[static_cast<std::size_t>(i)];
        s.glass += c.glass;
        s.binder += c.binder;
        s.glassColumn += c.glassColumn;
        s.binderColumn += c.binderColumn;
        s.glassBinderColumn += c.glassBinderColumn;
        all.glass += c.glass;
        all.binder += c.binder;
        all.glassTotal += c.glassTotal;
        all.binderTotal += c.binderTotal;
        all.glassBinderTotal += c.glassBinderTotal;
        total += c.glassTotal / (lattice.columnWidth(i) * lattice.cell * static_cast<double>(rows));
    }
    for (std::size_t i = 0; i < n; ++i)
    {
        const MatCell& s = column[i];
        const double area
            = lattice.columnWidth(static_cast<long>(i)) * lattice.cell * static_cast<double>(rows);
        profile.areaWeight[i] = {s.glass / area, std::sqrt(s.glassColumn) / area};
        profile.loi[i]
            = lossOnIgnition(s.glass, s.binder, s.glassColumn, s.binderColumn, s.glassBinderColumn);
    }
    profile.loiAll
        = lossOnIgnition(all.glass, all.binder, all.glassTotal, all.binderTotal, all.glassBinderTotal);
    // var(mean) = var(sum_j G_j / A_j) / n^2, with sum over cells g_i T_i / A_j over the mean area
    profile.meanVariance = total / meanArea / static_cast<double>(n * n);
    return profile;
}

NonUniformity nonUniformity(const AcrossProfile& profile)
{
    NonUniformity u;
    const auto n = static_cast<double>(profile.areaWeight.size());
    if (!(n > 0.0))
        return u;
    double meanVar = 0.0;
    for (const ValueWithError& p : profile.areaWeight)
    {
        u.mean += p.value / n;
        meanVar += p.error * p.error / n;
    }
    if (!(u.mean > 0.0))
        return u;
    double s2 = 0.0;
    for (const ValueWithError& p : profile.areaWeight)
        s2 += (p.value - u.mean) * (p.value - u.mean) / n;
    const double noise2 = std::max(meanVar - profile.meanVariance, 0.0);
    const double real2 = std::max(s2 - noise2, 0.0);
    const double spread = std::sqrt(2.0 * noise2 * noise2 / n + 4.0 * real2 * noise2 / n);
    u.observed = std::sqrt(s2) / u.mean;
    u.noise = std::sqrt(noise2) / u.mean;
    u.real = std::sqrt(real2) / u.mean;
    u.realUpper = std::sqrt(real2 + 2.0 * spread) / u.mean;
    return u;
}

} // namespace dropletFiber
