#include "laydown/MatMap.hpp"

#include <cmath>
#include <stdexcept>

namespace dropletFiber
{

MatMap::MatMap(double cell, double acrossMin, double acrossMax)
    : cell_(cell), acrossMin_(acrossMin), acrossMax_(acrossMax)
{
    if (!(cell > 0.0))
        throw std::invalid_argument("MatMap: the cell size must be > 0");
    if (!(acrossMax > acrossMin))
        throw std::invalid_argument("MatMap: the belt's width must be > 0");
}

long MatMap::widthColumns() const
{
    return static_cast<long>(std::ceil((acrossMax_ - acrossMin_) / cell_ - 1e-9));
}

long MatMap::column(double across) const
{
    return static_cast<long>(std::floor((across - acrossMin_) / cell_));
}

long MatMap::row(double along) const
{
    return static_cast<long>(std::floor(along / cell_));
}

double orientationOrder(const Eigen::Vector3d& orientation)
{
    const double across2 = orientation.x() * orientation.x();
    const double along2 = orientation.y() * orientation.y();
    const double inPlane = across2 + along2;
    return inPlane > 0.0 ? (along2 - across2) / inPlane : 0.0;
}

void MatMap::add(const LaidFiber& fiber)
{
    MatCell& c = cells_[{column(fiber.across), row(fiber.along)}];
    const double n = fiber.represents;
    c.glass += n * fiber.glassMass;
    c.binder += n * fiber.binderMass;
    c.fibers += n;
    c.orientationSum += n * fiber.glassMass * orientationOrder(fiber.orientation);
}

MatCell MatMap::total() const
{
    MatCell t;
    for (const auto& [key, c] : cells_)
    {
        t.glass += c.glass;
        t.binder += c.binder;
        t.fibers += c.fibers;
        t.orientationSum += c.orientationSum;
    }
    return t;
}

std::vector<double> MatMap::acrossProfile(long rowFrom, long rowTo) const
{
    const long columns = widthColumns();
    std::vector<double> profile(static_cast<std::size_t>(std::max(columns, 0L)), 0.0);
    const long rows = rowTo - rowFrom + 1;
    if (rows <= 0)
        return profile;
    for (const auto& [key, c] : cells_)
    {
        const auto [i, j] = key;
        if (i >= 0 && i < columns && j >= rowFrom && j <= rowTo)
            profile[static_cast<std::size_t>(i)] += c.glass;
    }
    // The last column may be cut by the belt's edge: its area is what lies on the belt
    for (long i = 0; i < columns; ++i)
    {
        const double width = std::min(cell_, acrossMax_ - (acrossMin_ + i * cell_));
        profile[static_cast<std::size_t>(i)] /= width * cell_ * static_cast<double>(rows);
    }
    return profile;
}

double MatMap::variation(const std::vector<double>& profile)
{
    if (profile.empty())
        return 0.0;
    double mean = 0.0;
    for (double v : profile)
        mean += v;
    mean /= static_cast<double>(profile.size());
    if (!(mean > 0.0))
        return 0.0;
    double var = 0.0;
    for (double v : profile)
        var += (v - mean) * (v - mean);
    return std::sqrt(var / static_cast<double>(profile.size())) / mean;
}

} // namespace dropletFiber
