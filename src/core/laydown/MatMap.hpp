// MatMap: the primary mat on the belt as a map of square cells across x along the belt
// (docs/model.md sec. 11): per cell the glass and binder laid there and the physical
// fibers, each laid fiber spread over the cells of its footprint (Footprint.hpp: its own
// line along its length, its population around it). With them the sums its statistical
// error needs (P60): every computed fiber is an independent draw, so a sum of the fibers'
// contributions c_i has the variance sum c_i^2, and a column's, sum C_i^2 (C_i a fiber's
// part of the column), kept per cell as sum c_i C_i; the map's likewise.
// Figures per cell: glass and binder area weight (kg/m^2), LOI = binder / (glass +
// binder), fibers per m^2, and the orientation order <cos 2 theta> (glass-weighted,
// theta the angle of a fiber's projection on the belt to the belt's motion: 1 all along
// the belt, -1 all across, 0 random in the plane).
// Cells are kept where something was laid (sparse); the across origin is acrossMin (the
// belt's edge), along from 0. Sums add up exactly in laying order, so a map rebuilt from
// the same fibers in the same order is the same to the bit.
#pragma once

#include "laydown/Belt.hpp"
#include "laydown/Footprint.hpp"

#include <array>
#include <map>
#include <utility>
#include <vector>

namespace dropletFiber
{

struct MatCell
{
    double glass = 0.0;          // kg
    double binder = 0.0;         // kg
    double fibers = 0.0;         // physical fibers
    double orientationSum = 0.0; // sum of glass x cos 2 theta
    // The error sums (kg^2) over the computed fibers i, c_i its glass (g) or binder (b)
    // here, C_i its glass or binder in this column of the map, T_i its glass on the map
    double glassSquares = 0.0;      // sum g_i^2
    double binderSquares = 0.0;     // sum b_i^2
    double glassBinder = 0.0;       // sum g_i b_i
    double glassColumn = 0.0;       // sum g_i G_i
    double binderColumn = 0.0;      // sum b_i B_i
    double glassBinderColumn = 0.0; // sum g_i B_i
    double glassTotal = 0.0;        // sum g_i T_i
    double binderTotal = 0.0;       // sum b_i U_i (U_i its binder on the map)
    double glassBinderTotal = 0.0;  // sum g_i U_i
    double computed = 0.0;          // the computed fibers behind it: sum of their shares here

    // The sums in restart order (the state's lists); setSums reads them back.
    static constexpr int sumCount = 14;
    std::array<double, sumCount> sums() const;
    void setSums(const std::array<double, sumCount>& values);
};

class MatMap
{
public:
    // Cells of size `cell` [m] from across = acrossMin; throws unless cell > 0.
    MatMap(double cell, double acrossMin, double acrossMax);

    double cell() const { return lattice_.cell; }
    double acrossMin() const { return lattice_.acrossMin; }
    double acrossMax() const { return lattice_.acrossMax; }
    // The cells' lattice (its columns across the belt's width, Footprint.hpp).
    const MapLattice& lattice() const { return lattice_; }

    // Lays the fiber over its footprint (and adds its error sums).
    void add(const LaidFiber& fiber);

    // (column, row) -> cell, in order.
    using Cells = std::map<std::pair<long, long>, MatCell>;
    const Cells& cells() const { return cells_; }
    // Restores a cell (restart).
    void setCell(long column, long row, const MatCell& value) { cells_[{column, row}] = value; }

    // Totals over all cells. The profile across over rows, with its errors and CoV:
    // MatUncertainty.hpp.
    MatCell total() const;

private:
    MapLattice lattice_;
    Cells cells_;
};

// cos 2 theta of an orientation (across, along, normal components): of its projection
// on the belt; 0 for a fiber standing normal to the belt.
double orientationOrder(const Eigen::Vector3d& orientation);

} // namespace dropletFiber
