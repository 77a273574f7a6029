// PathWeightBatch: the CPU check and the stage loops of the batched deposit (see
// PathWeightBatch.hpp). The stage loops are compiled for AVX2 + FMA (namespace avx2 between
// DROPLETFIBER_AVX2_BEGIN and END, KernelBuild.hpp), the rest of the file for the build's
// target: it keeps the working memory (std::vector code must stay default-target) and calls
// the loops only on a CPU that has AVX2 and FMA.
#include "grid/PathWeightBatch.hpp"

#include "grid/KernelBuild.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#if DROPLETFIBER_BATCHED_KERNEL

#include "grid/BranchFreeErfc.hpp"
#include "grid/BranchFreeExp.hpp"
#include "grid/Lanes.hpp"
#include "grid/PathIntegralClosedForm.hpp"

DROPLETFIBER_AVX2_BEGIN

namespace dropletFiber::avx2
{

namespace
{

static_assert(laneCount == PathWeightBatch::laneCount, "PathWeightBatch::laneCount is the lanes' width");

// Pads a list of positions to whole lanes by repeating its last entry (evaluating an entry
// twice writes the same values twice).
std::size_t padToLanes(std::uint32_t* list, std::size_t count)
{
    for (; count % laneCount != 0; ++count)
    {
        list[count] = list[count - 1];
    }
    return count;
}

Lanes gatherLanes(const double* values, const std::uint32_t* positions)
{
    Lanes a;
    for (int lane = 0; lane < laneCount; ++lane)
    {
        a[lane] = values[positions[lane]];
    }
    return a;
}

void scatterLanes(double* values, const std::uint32_t* positions, Lanes a)
{
    for (int lane = 0; lane < laneCount; ++lane)
    {
        values[positions[lane]] = a[lane];
    }
}

// The scaled erfc's interval 0 (small), 1 (middle) or 2 (large) of BranchFreeErfc.hpp.
// (A template, not lambdas: GCC does not give lambdas the AVX2 region's target.)
template <int interval>
FractionOf<Lanes> erfcScaledPartsIn(Lanes x)
{
    if constexpr (interval == 0)
    {
        return erfcScaledPartsSmall(x);
    }
    else if constexpr (interval == 1)
    {
        return erfcScaledPartsMiddle(x);
    }
    else
    {
        return erfcScaledPartsLarge(x);
    }
}

// Evaluates one interval of the scaled erfc for the listed ends.
template <int interval>
void erfcScaledPartsAt(const std::uint32_t* list, std::size_t count, const double* x, double* numerators,
                       double* denominators)
{
    for (std::size_t e = 0; e < count; e += laneCount)
    {
        const FractionOf<Lanes> parts = erfcScaledPartsIn<interval>(magnitude(gatherLanes(x, list + e)));
        scatterLanes(numerators, list + e, parts.numerator);
        scatterLanes(denominators, list + e, parts.denominator);
    }
}

// PathWeightBatch::omegas with its working memory: values 11 count doubles, indices
// 8 count + laneCount.
void omegasInLanes(const PathWeight& path, const double* lambdaM, const double* d0Squared, double* omega,
                   std::size_t count, double* values, std::uint32_t* indices)
{
    const ParcelKernel& kernel = path.kernel();
    PathIntegralClosedForm closedForm;
    closedForm.length = path.length();
    closedForm.reachSquared = kernel.reach() * kernel.reach();
    closedForm.gamma = kernel.gamma();
    closedForm.sqrtGamma = std::sqrt(kernel.gamma());
    closedForm.inverseSqrtGamma = 1.0 / closedForm.sqrtGamma;
    closedForm.edgeExponent = kernel.edgeExponent();
    closedForm.edgeValue = kernel.edgeValue();
    const double inverseLength = 1.0 / path.length();
    // The negligible-weight cut (PathWeight::limitTo): nodes at or beyond it get 0, as in
    // omegaFromOffset; applied by moving them out of reach in stage 1 (a select, no branch).
    const Lanes cutoffSquared = splat<Lanes>(path.cutoffSquared());
    const Lanes outOfReach = splat<Lanes>(2.0 * closedForm.reachSquared);

    // The stages of PathIntegralClosedForm as separate short loops, so that the processor
    // overlaps many nodes (the whole formula is a dependency chain of ~700 instructions,
    // longer than the reorder window), and so that the exponentials and rational functions
    // are evaluated only where needed:
    //  1. interval and regime of every node (lanes);
    //  2. the nodes in the closed-form regime are packed to the front (no branch);
    //  3. their three Gaussians (lanes);
    //  4. their two ends sorted by the interval of the scaled erfc, each list evaluated
    //     with its own rational function (lanes; one rational per end instead of three);
    //  5. the formula (lanes), written to the node's place;
    //  6. the ~1 node per parcel in regime A or B with the per-node code.
    const std::size_t ends = 2 * count;
    double* x = values;                        // x1 of every node, then x2
    double* exponents = x + ends;              // exponent0, 1, 2; then exp of them in place
    double* numerators = exponents + 3 * count; // erfc parts of |x1|, then |x2|
    double* denominators = numerators + ends;
    double* width = denominators + ends;
    double* status = width + count;
    std::uint32_t* node = indices; // packed position -> node
    std::uint32_t* lists = node + count + laneCount;

    for (std::size_t n = 0; n < count; n += laneCount) // 1.
    {
        const Lanes d0 = loadLanes(d0Squared + n);
        const PathIntegralClosedForm::Interval<Lanes> interval
            = closedForm.interval(loadLanes(lambdaM + n), select(d0 < cutoffSquared, d0, outOfReach));
        storeLanes(x + n, interval.x1);
        storeLanes(x + count + n, interval.x2);
        storeLanes(exponents + n, interval.exponent0);
        storeLanes(exponents + count + n, interval.exponent1);
        storeLanes(exponents + 2 * count + n, interval.exponent2);
        storeLanes(width + n, interval.width);
        storeLanes(status + n, interval.status);
        storeLanes(omega + n, splat<Lanes>(0.0));
    }
    std::size_t packed = 0; // 2. (in place: packed <= n)
    for (std::size_t n = 0; n < count; ++n)
    {
        x[packed] = x[n];
        x[count + packed] = x[count + n];
        exponents[packed] = exponents[n];
        exponents[count + packed] = exponents[count + n];
        exponents[2 * count + packed] = exponents[2 * count + n];
        width[packed] = width[n];
        node[packed] = static_cast<std::uint32_t>(n);
        packed += status[n] > 0.0 ? 1 : 0;
    }
    if (packed > 0)
    {
        // Pad to whole lanes by repeating the last packed node (count is a multiple of
        // laneCount, so the padding stays within the arrays).
        const std::size_t last = packed - 1;
        while (packed % laneCount != 0)
        {
            x[packed] = x[last];
            x[count + packed] = x[count + last];
            for (int i = 0; i < 3; ++i)
            {
                exponents[i * count + packed] = exponents[i * count + last];
            }
            width[packed] = width[last];
            node[packed] = node[last];
            ++packed;
        }
        for (int i = 0; i < 3; ++i) // 3.
        {
            double* block = exponents + i * count;
            for (std::size_t p = 0; p < packed; p += laneCount)
            {
                storeLanes(block + p, branchFreeExp(loadLanes(block + p)));
            }
        }
        std::size_t listLength[3] = {0, 0, 0}; // 4. (the list is chosen by index, not by a branch)
        for (const std::size_t first : {std::size_t(0), count})
        {
            for (std::size_t end = first; end < first + packed; ++end)
            {
                const int interval = erfcScaledInterval(std::abs(x[end]));
                lists[static_cast<std::size_t>(interval) * ends + listLength[interval]] = static_cast<std::uint32_t>(end);
                ++listLength[interval];
            }
        }
        for (int interval = 0; interval < 3; ++interval)
        {
            std::uint32_t* list = lists + interval * ends;
            if (listLength[interval] == 0)
            {
                continue;
            }
            // ends is a multiple of laneCount: padding stays within this list's part.
            const std::size_t length = padToLanes(list, listLength[interval]);
            if (interval == 0)
            {
                erfcScaledPartsAt<0>(list, length, x, numerators, denominators);
            }
            else if (interval == 1)
            {
                erfcScaledPartsAt<1>(list, length, x, numerators, denominators);
            }
            else
            {
                erfcScaledPartsAt<2>(list, length, x, numerators, denominators);
            }
        }
        for (std::size_t p = 0; p < packed; p += laneCount) // 5.
        {
            PathIntegralClosedForm::Interval<Lanes> interval;
            interval.x1 = loadLanes(x + p);
            interval.x2 = loadLanes(x + count + p);
            interval.width = loadLanes(width + p);
            interval.status = splat<Lanes>(1.0);
            const FractionOf<Lanes> parts1{loadLanes(numerators + p), loadLanes(denominators + p)};
            const FractionOf<Lanes> parts2{loadLanes(numerators + count + p), loadLanes(denominators + count + p)};
            const Lanes integral = closedForm.integral(interval, loadLanes(exponents + p), loadLanes(exponents + count + p),
                                                       loadLanes(exponents + 2 * count + p), parts1, parts2);
            scatterLanes(omega, node + p, integral * inverseLength);
        }
    }
    for (std::size_t n = 0; n < count; ++n) // 6. (status < 0 only within the cut)
    {
        if (status[n] < 0.0)
        {
            omega[n] = path.integralAlongPath(lambdaM[n], d0Squared[n]) * inverseLength;
        }
    }
}

// PathWeightBatch::boxOmegas's projection: lambdaM and d0Squared of every node of the box
// (i fastest), then the padding to whole lanes (out of reach: omega 0). Here so that the
// projection is compiled for AVX2 + FMA too (PathWeight::project, inlined).
void projectBox(const PathWeight& path, const Eigen::Vector3d& start, const double* x, const double* y,
                const double* z, const std::array<int, 3>& lo, const std::array<int, 3>& hi, double* lambdaM,
                double* d0Squared, std::size_t padded)
{
    std::size_t n = 0;
    for (int k = lo[2]; k <= hi[2]; ++k)
    {
        const double oz = z[k] - start.z();
        for (int j = lo[1]; j <= hi[1]; ++j)
        {
            const double oy = y[j] - start.y();
            for (int i = lo[0]; i <= hi[0]; ++i, ++n)
            {
                path.project(Eigen::Vector3d(x[i] - start.x(), oy, oz), lambdaM[n], d0Squared[n]);
            }
        }
    }
    const double reach = path.kernel().reach();
    for (; n < padded; ++n)
    {
        lambdaM[n] = 0.0;
        d0Squared[n] = 2.0 * reach * reach;
    }
}

} // namespace

} // namespace dropletFiber::avx2

DROPLETFIBER_AVX2_END

#endif // DROPLETFIBER_BATCHED_KERNEL

namespace dropletFiber
{

bool PathWeightBatch::cpuSupported()
{
#if DROPLETFIBER_BATCHED_KERNEL
    // libgcc's (or compiler-rt's) CPUID query, which also checks that the operating system
    // saves the AVX registers (XGETBV). __builtin_cpu_init first: this may run before the
    // library's constructors (static initialisers of other code).
    static const bool supported = [] {
        __builtin_cpu_init();
        return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    }();
    return supported;
#else
    return false;
#endif
}

// The batched code must not start on a CPU without AVX2 + FMA (SIGILL): callers choose the
// per-node code there, so reaching this is a programming error.
void PathWeightBatch::requireCpu(const char* caller)
{
    if (!cpuSupported())
    {
        throw std::logic_error(std::string("PathWeightBatch::") + caller
                               + ": this build or CPU has no AVX2 + FMA kernel "
                                 "(use the per-node code; PathWeightBatch::cpuSupported)");
    }
}

void PathWeightBatch::omegas(const PathWeight& path, const double* lambdaM, const double* d0Squared, double* omega,
                             std::size_t count)
{
    requireCpu("omegas");
#if DROPLETFIBER_BATCHED_KERNEL
    if (values_.size() < 11 * count)
    {
        values_.resize(11 * count);
        indices_.resize(8 * count + laneCount);
    }
    avx2::omegasInLanes(path, lambdaM, d0Squared, omega, count, values_.data(), indices_.data());
#else
    (void)path, (void)lambdaM, (void)d0Squared, (void)omega, (void)count;
#endif
}

const double* PathWeightBatch::boxOmegas(const PathWeight& path, const Eigen::Vector3d& start, const double* x,
                                         const double* y, const double* z, const std::array<int, 3>& lo,
                                         const std::array<int, 3>& hi)
{
    std::size_t boxNodes = 1;
    for (int d = 0; d < 3; ++d)
    {
        boxNodes *= static_cast<std::size_t>(hi[d] >= lo[d] ? hi[d] - lo[d] + 1 : 0);
    }
    const std::size_t padded = (boxNodes + laneCount - 1) / laneCount * laneCount;
    if (boxOmega_.size() < padded)
    {
        boxLambda_.resize(padded);
        boxDistanceSquared_.resize(padded);
        boxOmega_.resize(padded);
    }
    requireCpu("boxOmegas"); // before projectBox: AVX2 code
#if DROPLETFIBER_BATCHED_KERNEL
    avx2::projectBox(path, start, x, y, z, lo, hi, boxLambda_.data(), boxDistanceSquared_.data(), padded);
#else
    (void)start, (void)x, (void)y, (void)z;
#endif
    omegas(path, boxLambda_.data(), boxDistanceSquared_.data(), boxOmega_.data(), padded);
    return boxOmega_.data();
}

} // namespace dropletFiber
