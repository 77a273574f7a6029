// SeparableLanes: the separable weights' per-node loops (SeparableWeight, docs/model.md P16)
// four doubles per instruction, for CPUs with AVX2 + FMA (KernelBuild.hpp: compiled into
// every x86-64 build, called only where PathWeightBatch::cpuSupported()). The portable
// loops stay in SeparableWeight.cpp and DensityGrid.cpp; these are their counterparts:
//  - row():            omega[i] = sum_q rowFactor[q] X_q(first + i), the Q terms of 16 nodes
//                      kept in four registers (omega written once, not read and written Q
//                      times as in the portable loop);
//  - gaussianTable():  one axis table X_q(i) = exp(-gamma (x_i - c)^2) with the inline
//                      branch-free exp (BranchFreeExp.hpp, within 1.01 ulp) instead of a
//                      libm call per entry;
//  - addWeightedRow(): node i's 7 accumulator values += omega[i] inverseSum totals[q],
//                      four nodes' 28 values as 7 registers;
//  - addRow():         both for one row, omega in registers (no call and no store of omega
//                      per row; the last 1-3 nodes' values in whole registers where they
//                      fill one): the deposit's rows of wide kernels, whose boxes are rows
//                      of ~10 nodes at 2 mm.
//
// Each value's arithmetic is the same whatever its position in the row, so a part of a row
// gives the same values, to the bit, as those positions of the whole row (grid blocks hold
// the whole grid's values to the bit): row() starts every node from rowFactor[0] X_0 (one
// multiplication) and adds q = 1, 2, ... with one FMA each, the last 1-3 nodes in a register
// loaded with a mask; addWeightedRow() rounds omega inverseSum, then one FMA per value, the last 1-3
// nodes with scalar FMAs. Against the portable loops (multiplication, then addition) the
// values differ by the FMA's missing rounding, ~1e-16 relative (SeparableLanesTest).
//
// Only pointers and doubles cross into the AVX2 code (KernelBuild.hpp, rule 5). The
// functions below are default-target entry points that call it: only where available()
// (SeparableWeight's vectorised(), DensityGrid::batchedKernel()), which they do not check
// again (they run once per row); elsewhere they would stop the program with an illegal
// instruction.
#pragma once

#include <cstddef>

namespace dropletFiber
{

struct SeparableLanes
{
    // Accumulator values per node (GridQuantities' nQuantities).
    static constexpr std::size_t quantities = 7;

    // True when this build has the AVX2 code and this CPU has AVX2 and FMA.
    static bool available();

    // omega[i] = sum_{q < points} rowFactor[q] factor[q stride + i] for i < count, q in
    // increasing order (1 <= points).
    static void row(const double* rowFactor, int points, const double* factor, std::size_t stride,
                    std::size_t count, double* omega);

    // table[i] = exp(-gamma (coordinate[i] - centre)^2) for i < count.
    static void gaussianTable(const double* coordinate, std::size_t count, double centre, double gamma,
                              double* table);

    // row() and addWeightedRow() in one pass, omega kept in registers: values[quantities i + q]
    // += (omega[i] inverseSum) totals[q] for i < count, q < 7, omega[i] as row() gives it:
    // the same values to the bit as row() then addWeightedRow().
    static void addRow(const double* rowFactor, int points, const double* factor, std::size_t stride,
                       std::size_t count, double inverseSum, const double* totals, double* values);

    // values[quantities i + q] += (omega[i] inverseSum) totals[q] for i < length, q < 7.
    static void addWeightedRow(const double* omega, std::size_t length, double inverseSum,
                               const double* totals, double* values);
};

} // namespace dropletFiber
