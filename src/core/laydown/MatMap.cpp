#include "laydown/MatMap.hpp"

#include <stdexcept>

namespace dropletFiber
{

MatMap::MatMap(double cell, double acrossMin, double acrossMax) : lattice_{cell, acrossMin, acrossMax}
{
    if (!(cell > 0.0))
        throw std::invalid_argument("MatMap: the cell size must be > 0");
    if (!(acrossMax > acrossMin))
        throw std::invalid_argument("MatMap: the belt's width must be > 0");
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
    const std::vector<CellShare> shares = footprint(fiber, lattice_);
    // Its own line and its population (P59); without a spread all N on the line
    const double n = fiber.represents;
    const bool spread = fiber.spread > 0.0 && n > 1.0;
    const double onLine = spread ? 1.0 : n, spreadOut = spread ? n - 1.0 : 0.0;
    const double order = orientationOrder(fiber.orientation);
    // Its physical fibers per cell; its glass and binder per column and on the map, for
    // the error sums
    std::vector<double> physical(shares.size());
    std::map<long, std::pair<double, double>> column;
    double total = 0.0, totalBinder = 0.0;
    for (std::size_t k = 0; k < shares.size(); ++k)
    {
        physical[k] = onLine * shares[k].line + spreadOut * shares[k].population;
        auto& [g, b] = column[shares[k].column];
        g += physical[k] * fiber.glassMass;
        b += physical[k] * fiber.binderMass;
        total += physical[k] * fiber.glassMass;
        totalBinder += physical[k] * fiber.binderMass;
    }
    for (std::size_t k = 0; k < shares.size(); ++k)
    {
        const double g = physical[k] * fiber.glassMass, b = physical[k] * fiber.binderMass;
        const auto& [G, B] = column[shares[k].column];
        MatCell& c = cells_[{shares[k].column, shares[k].row}];
        c.glass += g;
        c.binder += b;
        c.fibers += physical[k];
        c.orientationSum += g * order;
        c.glassSquares += g * g;
        c.binderSquares += b * b;
        c.glassBinder += g * b;
        c.glassColumn += g * G;
        c.binderColumn += b * B;
        c.glassBinderColumn += g * B;
        c.glassTotal += g * total;
        c.binderTotal += b * totalBinder;
        c.glassBinderTotal += g * totalBinder;
        c.computed += physical[k] / n;
    }
}

std::array<double, MatCell::sumCount> MatCell::sums() const
{
    return {glass,         binder,      fibers,           orientationSum, glassSquares,
            binderSquares, glassBinder, glassColumn,      binderColumn,   glassBinderColumn,
            glassTotal,    binderTotal, glassBinderTotal, computed};
}

void MatCell::setSums(const std::array<double, sumCount>& v)
{
    glass = v[0];
    binder = v[1];
    fibers = v[2];
    orientationSum = v[3];
    glassSquares = v[4];
    binderSquares = v[5];
    glassBinder = v[6];
    glassColumn = v[7];
    binderColumn = v[8];
    glassBinderColumn = v[9];
    glassTotal = v[10];
    binderTotal = v[11];
    glassBinderTotal = v[12];
    computed = v[13];
}

MatCell MatMap::total() const
{
    std::array<double, MatCell::sumCount> t{};
    for (const auto& [key, c] : cells_)
    {
        const auto v = c.sums();
        for (int k = 0; k < MatCell::sumCount; ++k)
            t[static_cast<std::size_t>(k)] += v[static_cast<std::size_t>(k)];
    }
    MatCell total;
    total.setSums(t);
    return total;
}

} // namespace dropletFiber
