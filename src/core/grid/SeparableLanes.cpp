// SeparableLanes: the separable weights' AVX2 + FMA loops (see SeparableLanes.hpp). The loops
// are compiled for AVX2 + FMA (namespace avx2 between DROPLETFIBER_AVX2_BEGIN and END,
// KernelBuild.hpp), the entry points below them for the build's target: they pass pointers
// and doubles only.
#include "grid/SeparableLanes.hpp"

#include "grid/KernelBuild.hpp"
#include "grid/PathWeightBatch.hpp"

#if DROPLETFIBER_BATCHED_KERNEL

#include "grid/BranchFreeExp.hpp"
#include "grid/Lanes.hpp"

#include <immintrin.h>

DROPLETFIBER_AVX2_BEGIN

namespace dropletFiber::avx2
{

namespace
{

// SeparableLanes::row for the 4 `blocks` nodes from position i on: the Q terms of each node
// summed in a register (rowFactor[0] X_0 rounded, then one FMA per further point).
template <int blocks>
inline void rowBlocks(const double* rowFactor, int points, const double* factor, std::size_t stride,
                      std::size_t i, double* omega)
{
    __m256d sum[blocks];
    const __m256d first = _mm256_broadcast_sd(rowFactor);
    for (int b = 0; b < blocks; ++b)
    {
        sum[b] = _mm256_mul_pd(first, _mm256_loadu_pd(factor + i + 4 * b));
    }
    for (int q = 1; q < points; ++q)
    {
        const __m256d r = _mm256_broadcast_sd(rowFactor + q);
        const double* f = factor + static_cast<std::size_t>(q) * stride + i;
        for (int b = 0; b < blocks; ++b)
        {
            sum[b] = _mm256_fmadd_pd(r, _mm256_loadu_pd(f + 4 * b), sum[b]);
        }
    }
    for (int b = 0; b < blocks; ++b)
    {
        _mm256_storeu_pd(omega + i + 4 * b, sum[b]);
    }
}

// The last `remaining` (1-3) nodes from position i on: the same operations in a register
// whose other lanes are masked when loading (not read; they hold 0).
inline __m256d omegaOfLast(const double* rowFactor, int points, const double* factor, std::size_t stride,
                           std::size_t i, std::size_t remaining)
{
    const __m256i mask = _mm256_cmpgt_epi64(_mm256_set1_epi64x(static_cast<long long>(remaining)),
                                            _mm256_setr_epi64x(0, 1, 2, 3));
    __m256d sum = _mm256_mul_pd(_mm256_broadcast_sd(rowFactor), _mm256_maskload_pd(factor + i, mask));
    for (int q = 1; q < points; ++q)
    {
        const double* f = factor + static_cast<std::size_t>(q) * stride + i;
        sum = _mm256_fmadd_pd(_mm256_broadcast_sd(rowFactor + q), _mm256_maskload_pd(f, mask), sum);
    }
    return sum;
}

// rowTail: those nodes' omega stored lane by lane (a masked store is slow on some CPUs: AMD
// Zen).
inline void rowTail(const double* rowFactor, int points, const double* factor, std::size_t stride,
                    std::size_t i, std::size_t remaining, double* omega)
{
    double lanes[4];
    _mm256_storeu_pd(lanes, omegaOfLast(rowFactor, points, factor, stride, i, remaining));
    for (std::size_t lane = 0; lane < remaining; ++lane)
    {
        omega[i + lane] = lanes[lane];
    }
}

void rowInLanes(const double* rowFactor, int points, const double* factor, std::size_t stride,
                std::size_t count, double* omega)
{
    // 16 nodes per pass: four independent FMA chains hide the FMA's latency, and each
    // point's factor is broadcast once per 16 nodes.
    std::size_t i = 0;
    for (; i + 16 <= count; i += 16)
    {
        rowBlocks<4>(rowFactor, points, factor, stride, i, omega);
    }
    for (; i + 4 <= count; i += 4)
    {
        rowBlocks<1>(rowFactor, points, factor, stride, i, omega);
    }
    if (i < count)
    {
        rowTail(rowFactor, points, factor, stride, i, count - i, omega);
    }
}

void gaussianTableInLanes(const double* coordinate, std::size_t count, double centre, double gamma,
                          double* table)
{
    const Lanes c = splat<Lanes>(centre);
    const Lanes minusGamma = splat<Lanes>(-gamma);
    std::size_t i = 0;
    for (; i + laneCount <= count; i += laneCount)
    {
        const Lanes s = loadLanes(coordinate + i) - c;
        storeLanes(table + i, branchFreeExp(minusGamma * s * s));
    }
    if (i < count)
    {
        // The last 1-3 entries through the same lane code (padded with the last one).
        double x[laneCount], e[laneCount];
        for (std::size_t lane = 0; lane < laneCount; ++lane)
        {
            x[lane] = coordinate[i + lane < count ? i + lane : count - 1];
        }
        const Lanes s = loadLanes(x) - c;
        storeLanes(e, branchFreeExp(minusGamma * s * s));
        for (std::size_t lane = 0; i + lane < count; ++lane)
        {
            table[i + lane] = e[lane];
        }
    }
}

// Four nodes' 28 values as 7 registers: lane l of register r is value m = 4 r + l, of node
// m / 7 and quantity m % 7. The node's weight per lane, as vpermpd's selector.
template <int r>
constexpr int weightSelector()
{
    int selector = 0;
    for (int lane = 0; lane < 4; ++lane)
    {
        selector |= ((4 * r + lane) / 7) << (2 * lane);
    }
    return selector;
}

template <int r>
inline void addLanes(__m256d weights, const __m256d* totals, double* values)
{
    const __m256d w = _mm256_permute4x64_pd(weights, weightSelector<r>());
    _mm256_storeu_pd(values + 4 * r, _mm256_fmadd_pd(w, totals[r], _mm256_loadu_pd(values + 4 * r)));
}

constexpr std::size_t q7 = SeparableLanes::quantities;
static_assert(q7 == 7, "the lane pattern below is for 7 quantities");

// Lane l of register r: totals[(4 r + l) % 7] (four nodes' 28 values).
inline void totalsPattern(const double* totals, __m256d* pattern)
{
    for (std::size_t r = 0; r < q7; ++r)
    {
        pattern[r] = _mm256_setr_pd(totals[(4 * r) % q7], totals[(4 * r + 1) % q7], totals[(4 * r + 2) % q7],
                                    totals[(4 * r + 3) % q7]);
    }
}

// The four nodes' 28 values from `values` on, += weights (per node) times the totals.
inline void addFourNodes(__m256d weights, const __m256d* pattern, double* values)
{
    addLanes<0>(weights, pattern, values);
    addLanes<1>(weights, pattern, values);
    addLanes<2>(weights, pattern, values);
    addLanes<3>(weights, pattern, values);
    addLanes<4>(weights, pattern, values);
    addLanes<5>(weights, pattern, values);
    addLanes<6>(weights, pattern, values);
}

// The last 1-3 nodes (their weights in the first lanes): the whole registers of values that
// lie within the row (7 nodes' values fill 7 / 4 registers), the last 1-3 values by scalar
// FMAs of the same rounding.
inline void addLastNodes(__m256d weights, std::size_t nodes, const __m256d* pattern, const double* totals,
                         double* values)
{
    const std::size_t whole = nodes * q7 / 4; // 1, 3 or 5
    addLanes<0>(weights, pattern, values);
    if (whole >= 3)
    {
        addLanes<1>(weights, pattern, values);
        addLanes<2>(weights, pattern, values);
    }
    if (whole >= 5)
    {
        addLanes<3>(weights, pattern, values);
        addLanes<4>(weights, pattern, values);
    }
    double weight[4];
    _mm256_storeu_pd(weight, weights);
    for (std::size_t m = 4 * whole; m < nodes * q7; ++m)
    {
        values[m] = _mm_cvtsd_f64(
            _mm_fmadd_sd(_mm_set_sd(weight[m / q7]), _mm_set_sd(totals[m % q7]), _mm_set_sd(values[m])));
    }
}

// omega of the 4 nodes from position i on: rowBlocks<1>'s operations, the row factors
// broadcast (r). Points: Q when it is a compile-time constant (the loops unrolled), 0 for
// `points`.
template <int Points>
inline __m256d omegaOfFour(const __m256d* r, int points, const double* factor, std::size_t stride,
                           std::size_t i)
{
    const int n = Points > 0 ? Points : points;
    __m256d sum = _mm256_mul_pd(r[0], _mm256_loadu_pd(factor + i));
    for (int q = 1; q < n; ++q)
    {
        sum = _mm256_fmadd_pd(r[q], _mm256_loadu_pd(factor + static_cast<std::size_t>(q) * stride + i), sum);
    }
    return sum;
}

// One row of addRows: omega of 4 nodes at a time, then their 28 values.
template <int Points>
inline void addRowWith(const double* rowFactor, int points, const double* factor, std::size_t stride,
                       std::size_t count, __m256d scale, const __m256d* pattern, const double* totals,
                       double* values)
{
    const int n = Points > 0 ? Points : points;
    __m256d r[Points > 0 ? Points : SeparableLanes::maximumPoints];
    for (int q = 0; q < n; ++q)
    {
        r[q] = _mm256_broadcast_sd(rowFactor + q);
    }
    std::size_t i = 0;
    for (; i + 16 <= count; i += 16, values += 16 * q7)
    {
        // Four independent sums at a time (the FMA's latency hidden on long rows)
        const __m256d omega0 = omegaOfFour<Points>(r, points, factor, stride, i);
        const __m256d omega1 = omegaOfFour<Points>(r, points, factor, stride, i + 4);
        const __m256d omega2 = omegaOfFour<Points>(r, points, factor, stride, i + 8);
        const __m256d omega3 = omegaOfFour<Points>(r, points, factor, stride, i + 12);
        addFourNodes(_mm256_mul_pd(omega0, scale), pattern, values);
        addFourNodes(_mm256_mul_pd(omega1, scale), pattern, values + 4 * q7);
        addFourNodes(_mm256_mul_pd(omega2, scale), pattern, values + 8 * q7);
        addFourNodes(_mm256_mul_pd(omega3, scale), pattern, values + 12 * q7);
    }
    for (; i + 4 <= count; i += 4, values += 4 * q7)
    {
        const __m256d omega = omegaOfFour<Points>(r, points, factor, stride, i);
        addFourNodes(_mm256_mul_pd(omega, scale), pattern, values);
    }
    if (i < count)
    {
        const __m256d omega = omegaOfLast(rowFactor, n, factor, stride, i, count - i);
        addLastNodes(_mm256_mul_pd(omega, scale), count - i, pattern, totals, values);
    }
}

template <int Points>
void addRowsWith(const SeparableLanes::BoxRows& box, double inverseSum, const double* totals)
{
    __m256d pattern[q7];
    totalsPattern(totals, pattern);
    const __m256d scale = _mm256_set1_pd(inverseSum);
    const auto points = static_cast<std::size_t>(Points > 0 ? Points : box.points);
    const std::size_t rowValues = box.count * q7;
    double rowFactor[SeparableLanes::maximumPoints];
    for (std::size_t k = 0; k < box.layers; ++k)
    {
        const double* z = box.z + k * points;
        for (std::size_t j = 0; j < box.rows; ++j)
        {
            const double* weightedY = box.weightedY + j * points;
            for (std::size_t q = 0; q < points; ++q)
            {
                rowFactor[q] = weightedY[q] * z[q];
            }
            const std::size_t offset = k * box.layerStride + j * box.rowStride;
            if (offset + box.prefetchAhead + rowValues <= box.available)
            {
                const double* ahead = box.values + offset + box.prefetchAhead;
#pragma GCC unroll 4
                for (std::size_t m = 0; m < rowValues; m += 8) // 64-byte lines
                {
                    __builtin_prefetch(ahead + m, 1);
                }
            }
            addRowWith<Points>(rowFactor, box.points, box.factor, box.stride, box.count, scale, pattern,
                               totals, box.values + offset);
        }
    }
}

void addRowsInLanes(const SeparableLanes::BoxRows& box, double inverseSum, const double* totals)
{
    // The Q of the wide kernels wideKernelBench weighs (1 stationary, 4-8 moving) unrolled
    switch (box.points)
    {
        case 1:
            return addRowsWith<1>(box, inverseSum, totals);
        case 4:
            return addRowsWith<4>(box, inverseSum, totals);
        case 5:
            return addRowsWith<5>(box, inverseSum, totals);
        case 6:
            return addRowsWith<6>(box, inverseSum, totals);
        default:
            return addRowsWith<0>(box, inverseSum, totals);
    }
}

void addWeightedRowInLanes(const double* omega, std::size_t length, double inverseSum, const double* totals,
                           double* values)
{
    __m256d pattern[q7];
    totalsPattern(totals, pattern);
    const __m256d scale = _mm256_set1_pd(inverseSum);
    std::size_t i = 0;
    for (; i + 4 <= length; i += 4, values += 4 * q7)
    {
        addFourNodes(_mm256_mul_pd(_mm256_loadu_pd(omega + i), scale), pattern, values);
    }
    for (; i < length; ++i, values += q7)
    {
        // The same rounding per value: omega inverseSum, then one FMA.
        const __m128d weight = _mm_mul_sd(_mm_set_sd(omega[i]), _mm_set_sd(inverseSum));
        for (std::size_t q = 0; q < q7; ++q)
        {
            values[q] = _mm_cvtsd_f64(_mm_fmadd_sd(weight, _mm_set_sd(totals[q]), _mm_set_sd(values[q])));
        }
    }
}

// Table t's term i, 0 beyond its length.
inline double termOf(const double* const* tables, const std::size_t* lengths, std::size_t t, std::size_t i)
{
    return i < lengths[t] ? tables[t][i] : 0.0;
}

void compensatedSumsInLanes(const double* const* tables, const std::size_t* lengths, std::size_t count,
                            double* sums)
{
    // Lanes beyond `count`, and a table's lane beyond its length, add 0: its sum and
    // compensation then stay as they are (the sums are positive)
    const double* table[4] = {nullptr, nullptr, nullptr, nullptr};
    std::size_t length[4] = {0, 0, 0, 0};
    std::size_t longest = 0;
    for (std::size_t t = 0; t < count; ++t)
    {
        table[t] = tables[t];
        length[t] = lengths[t];
        longest = lengths[t] > longest ? lengths[t] : longest;
    }
    __m256d sum = _mm256_setzero_pd(), compensation = _mm256_setzero_pd();
    for (std::size_t i = 0; i < longest; ++i)
    {
        const __m256d f = _mm256_setr_pd(termOf(table, length, 0, i), termOf(table, length, 1, i),
                                         termOf(table, length, 2, i), termOf(table, length, 3, i));
        const __m256d next = _mm256_add_pd(sum, f);
        const __m256d sumLarger = _mm256_add_pd(_mm256_sub_pd(sum, next), f);
        const __m256d termLarger = _mm256_add_pd(_mm256_sub_pd(f, next), sum);
        const __m256d larger = _mm256_cmp_pd(sum, f, _CMP_GE_OQ);
        compensation = _mm256_add_pd(compensation, _mm256_blendv_pd(termLarger, sumLarger, larger));
        sum = next;
    }
    double result[4];
    _mm256_storeu_pd(result, _mm256_add_pd(sum, compensation));
    for (std::size_t t = 0; t < count; ++t)
    {
        sums[t] = result[t];
    }
}

} // namespace

} // namespace dropletFiber::avx2

DROPLETFIBER_AVX2_END

#endif // DROPLETFIBER_BATCHED_KERNEL

namespace dropletFiber
{

bool SeparableLanes::available()
{
    return PathWeightBatch::cpuSupported();
}

void SeparableLanes::row(const double* rowFactor, int points, const double* factor, std::size_t stride,
                         std::size_t count, double* omega)
{
#if DROPLETFIBER_BATCHED_KERNEL
    avx2::rowInLanes(rowFactor, points, factor, stride, count, omega);
#else
    (void)rowFactor, (void)points, (void)factor, (void)stride, (void)count, (void)omega;
#endif
}

void SeparableLanes::gaussianTable(const double* coordinate, std::size_t count, double centre, double gamma,
                                   double* table)
{
#if DROPLETFIBER_BATCHED_KERNEL
    avx2::gaussianTableInLanes(coordinate, count, centre, gamma, table);
#else
    (void)coordinate, (void)count, (void)centre, (void)gamma, (void)table;
#endif
}

void SeparableLanes::addRows(const BoxRows& box, double inverseSum, const double* totals)
{
#if DROPLETFIBER_BATCHED_KERNEL
    avx2::addRowsInLanes(box, inverseSum, totals);
#else
    (void)box, (void)inverseSum, (void)totals;
#endif
}

void SeparableLanes::compensatedSums(const double* const* tables, const std::size_t* lengths,
                                     std::size_t count, double* sums)
{
#if DROPLETFIBER_BATCHED_KERNEL
    avx2::compensatedSumsInLanes(tables, lengths, count, sums);
#else
    (void)tables, (void)lengths, (void)count, (void)sums;
#endif
}

void SeparableLanes::addWeightedRow(const double* omega, std::size_t length, double inverseSum,
                                    const double* totals, double* values)
{
#if DROPLETFIBER_BATCHED_KERNEL
    avx2::addWeightedRowInLanes(omega, length, inverseSum, totals, values);
#else
    (void)omega, (void)length, (void)inverseSum, (void)totals, (void)values;
#endif
}

} // namespace dropletFiber
