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
//  - compensatedSums(): the normalising sum's per-axis sums, four tables at a time (their
//                      additions are a chain of dependent operations per table);
//  - addWeightedRow(): node i's 7 accumulator values += omega[i] inverseSum totals[q],
//                      four nodes' 28 values as 7 registers;
//  - addRows():        both for every row of a box in one call, omega in registers (no
//                      call, no store of omega per row, the totals' lane pattern set once;
//                      the last 1-3 nodes' values in whole registers where they fill one):
//                      the deposit of wide kernels, whose boxes are ~100 rows of ~10 nodes
//                      at 2 mm.
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
    // The rows of a box to add (addRows): rows x layers rows of `count` nodes each, their
    // values at `values` (7 per node, contiguous along a row) with strides in doubles.
    struct BoxRows
    {
        const double* weightedY = nullptr; // W_q Y_q(j), point-major, from the box's first row on
        const double* z = nullptr;         // Z_q(k), point-major, from its first layer on
        std::size_t rows = 0;              // in j
        std::size_t layers = 0;            // in k
        int points = 1;
        const double* factor = nullptr; // X_q from the rows' first node on, q-major
        std::size_t stride = 0;         // X_q to X_{q+1}
        std::size_t count = 0;          // nodes per row
        double* values = nullptr;       // the first row's first node's
        std::size_t rowStride = 0;      // doubles from a row's values to the next row's
        std::size_t layerStride = 0;    // ... to the next layer's
        // Each row's values prefetchAhead doubles further are requested while it is added,
        // where they lie within the `available` doubles from `values` on.
        std::size_t prefetchAhead = 0;
        std::size_t available = 0;
    };

    // Accumulator values per node (GridQuantities' nQuantities).
    static constexpr std::size_t quantities = 7;
    // Most Gauss-Legendre points of a row factor (SeparableWeight::maximumPoints).
    static constexpr int maximumPoints = 12;

    // True when this build has the AVX2 code and this CPU has AVX2 and FMA.
    static bool available();

    // omega[i] = sum_{q < points} rowFactor[q] factor[q stride + i] for i < count, q in
    // increasing order (1 <= points).
    static void row(const double* rowFactor, int points, const double* factor, std::size_t stride,
                    std::size_t count, double* omega);

    // table[i] = exp(-gamma (coordinate[i] - centre)^2) for i < count.
    static void gaussianTable(const double* coordinate, std::size_t count, double centre, double gamma,
                              double* table);

    // row() and addWeightedRow() for every row of the box in one pass, k outermost, the row
    // factor rowFactor[q] = W_q Y_q(j) Z_q(k), omega kept in registers: values[quantities i
    // + q] of each row += (omega[i] inverseSum) totals[q], the same values to the bit as
    // row() then addWeightedRow() (points <= maximumPoints).
    static void addRows(const BoxRows& box, double inverseSum, const double* totals);

    // sums[t] = Neumaier's compensated sum of tables[t][0], ..., tables[t][lengths[t] - 1]
    // (positive terms) for t < count <= 4, in lanes, one table per lane: the same operations
    // per table as SeparableWeight::sum's portable loop, so the same sums to the bit.
    static void compensatedSums(const double* const* tables, const std::size_t* lengths, std::size_t count,
                                double* sums);

    // values[quantities i + q] += (omega[i] inverseSum) totals[q] for i < length, q < 7.
    static void addWeightedRow(const double* omega, std::size_t length, double inverseSum,
                               const double* totals, double* values);
};

} // namespace dropletFiber
