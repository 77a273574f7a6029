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
#include "grid/CodyErfcRationals.hpp" // DROPLETFIBER_ALWAYS_INLINE
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

// The stages of PathIntegralClosedForm as separate short loops, so that the processor
// overlaps many nodes (the whole formula is a dependency chain of ~700 instructions, longer
// than the reorder window), and so that the exponentials and rational functions are
// evaluated only where needed:
//  1. interval and regime of every node (lanes; classifyNodes);
//  2. the nodes in the closed-form regime are packed to the front (no branch;
//     packClosedFormNodes);
//  3. their three Gaussians (lanes; exponentialsInPlace);
//  4. their two ends sorted by the interval of the scaled erfc, each list evaluated with
//     its own rational function (lanes; one rational per end instead of three;
//     erfcScaledPartsOfEnds);
//  5. the formula (lanes), written to the node's place (closedFormOmegas);
//  6. the ~1 node per parcel in regime A or B with the per-node code (exactOmegas).
// Each stage is force-inlined into omegasInLanes: one function as the batched loop was
// written and measured.

// The stages' working memory, carved from PathWeightBatch::omegas's values (11 count
// doubles) and indices (8 count + laneCount).
struct Stages
{
    std::size_t count;  // nodes, a multiple of laneCount
    std::size_t ends;   // 2 count: x1 of every node, then x2
    double* x;          // x1 of every node, then x2
    double* exponents;  // exponent0, 1, 2; then exp of them in place
    double* numerators; // erfc parts of |x1|, then |x2|
    double* denominators;
    double* width;
    double* status;
    std::uint32_t* node;  // packed position -> node
    std::uint32_t* lists; // stage 4: the ends per interval of the scaled erfc
};

DROPLETFIBER_ALWAYS_INLINE Stages stagesIn(std::size_t count, double* values, std::uint32_t* indices)
{
    Stages s;
    s.count = count;
    s.ends = 2 * count;
    s.x = values;
    s.exponents = s.x + s.ends;
    s.numerators = s.exponents + 3 * count;
    s.denominators = s.numerators + s.ends;
    s.width = s.denominators + s.ends;
    s.status = s.width + count;
    s.node = indices;
    s.lists = s.node + count + laneCount;
    return s;
}

DROPLETFIBER_ALWAYS_INLINE PathIntegralClosedForm closedFormOf(const PathWeight& path)
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
    return closedForm;
}

// 1. Every node's interval and regime; omega set to 0. The negligible-weight cut
// (PathWeight::limitTo): nodes at or beyond it get 0, as in omegaFromOffset; applied by
// moving them out of reach (a select, no branch).
DROPLETFIBER_ALWAYS_INLINE void classifyNodes(const PathIntegralClosedForm& closedForm,
                                              double pathCutoffSquared, const double* lambdaM,
                                              const double* d0Squared, double* omega, const Stages& s)
{
    const Lanes cutoffSquared = splat<Lanes>(pathCutoffSquared);
    const Lanes outOfReach = splat<Lanes>(2.0 * closedForm.reachSquared);
    for (std::size_t n = 0; n < s.count; n += laneCount)
    {
        const Lanes d0 = loadLanes(d0Squared + n);
        const PathIntegralClosedForm::Interval<Lanes> interval
            = closedForm.interval(loadLanes(lambdaM + n), select(d0 < cutoffSquared, d0, outOfReach));
        storeLanes(s.x + n, interval.x1);
        storeLanes(s.x + s.count + n, interval.x2);
        storeLanes(s.exponents + n, interval.exponent0);
        storeLanes(s.exponents + s.count + n, interval.exponent1);
        storeLanes(s.exponents + 2 * s.count + n, interval.exponent2);
        storeLanes(s.width + n, interval.width);
        storeLanes(s.status + n, interval.status);
        storeLanes(omega + n, splat<Lanes>(0.0));
    }
}

// Copies the stage values of node `from` to packed position `to`.
DROPLETFIBER_ALWAYS_INLINE void copyNodeStages(const Stages& s, std::size_t from, std::size_t to)
{
    s.x[to] = s.x[from];
    s.x[s.count + to] = s.x[s.count + from];
    for (std::size_t i = 0; i < 3; ++i)
    {
        s.exponents[i * s.count + to] = s.exponents[i * s.count + from];
    }
    s.width[to] = s.width[from];
}

// 2. The nodes in the closed-form regime packed to the front (in place: packed <= n),
// padded to whole lanes by repeating the last one. Returns their padded count.
DROPLETFIBER_ALWAYS_INLINE std::size_t packClosedFormNodes(const Stages& s)
{
    std::size_t packed = 0;
    for (std::size_t n = 0; n < s.count; ++n)
    {
        copyNodeStages(s, n, packed);
        s.node[packed] = static_cast<std::uint32_t>(n);
        packed += s.status[n] > 0.0 ? 1 : 0;
    }
    if (packed == 0)
    {
        return 0;
    }
    // count is a multiple of laneCount, so the padding stays within the arrays.
    const std::size_t last = packed - 1;
    for (; packed % laneCount != 0; ++packed)
    {
        copyNodeStages(s, last, packed);
        s.node[packed] = s.node[last];
    }
    return packed;
}

// 3. The three Gaussians of the packed nodes, exp of the exponents in place.
DROPLETFIBER_ALWAYS_INLINE void exponentialsInPlace(const Stages& s, std::size_t packed)
{
    for (std::size_t i = 0; i < 3; ++i)
    {
        double* block = s.exponents + i * s.count;
        for (std::size_t p = 0; p < packed; p += laneCount)
        {
            storeLanes(block + p, branchFreeExp(loadLanes(block + p)));
        }
    }
}

// 4. The scaled erfc's numerator and denominator at both ends of the packed nodes: the
// ends listed per interval of the scaled erfc (the list chosen by index, not by a
// branch), each list evaluated with its own rational function.
DROPLETFIBER_ALWAYS_INLINE void erfcScaledPartsOfEnds(const Stages& s, std::size_t packed)
{
    std::size_t listLength[3] = {0, 0, 0};
    for (const std::size_t first : {std::size_t(0), s.count})
    {
        for (std::size_t end = first; end < first + packed; ++end)
        {
            const int interval = erfcScaledInterval(std::abs(s.x[end]));
            s.lists[static_cast<std::size_t>(interval) * s.ends + listLength[interval]]
                = static_cast<std::uint32_t>(end);
            ++listLength[interval];
        }
    }
    for (int interval = 0; interval < 3; ++interval)
    {
        std::uint32_t* list = s.lists + interval * s.ends;
        if (listLength[interval] == 0)
        {
            continue;
        }
        // ends is a multiple of laneCount: padding stays within this list's part.
        const std::size_t length = padToLanes(list, listLength[interval]);
        if (interval == 0)
        {
            erfcScaledPartsAt<0>(list, length, s.x, s.numerators, s.denominators);
        }
        else if (interval == 1)
        {
            erfcScaledPartsAt<1>(list, length, s.x, s.numerators, s.denominators);
        }
        else
        {
            erfcScaledPartsAt<2>(list, length, s.x, s.numerators, s.denominators);
        }
    }
}

// 5. The closed form of the packed nodes, omega written to each node's place.
DROPLETFIBER_ALWAYS_INLINE void closedFormOmegas(const PathIntegralClosedForm& closedForm,
                                                 double inverseLength, const Stages& s, std::size_t packed,
                                                 double* omega)
{
    for (std::size_t p = 0; p < packed; p += laneCount)
    {
        PathIntegralClosedForm::Interval<Lanes> interval;
        interval.x1 = loadLanes(s.x + p);
        interval.x2 = loadLanes(s.x + s.count + p);
        interval.width = loadLanes(s.width + p);
        interval.status = splat<Lanes>(1.0);
        const FractionOf<Lanes> parts1{loadLanes(s.numerators + p), loadLanes(s.denominators + p)};
        const FractionOf<Lanes> parts2{loadLanes(s.numerators + s.count + p),
                                       loadLanes(s.denominators + s.count + p)};
        const Lanes integral
            = closedForm.integral(interval, loadLanes(s.exponents + p), loadLanes(s.exponents + s.count + p),
                                  loadLanes(s.exponents + 2 * s.count + p), parts1, parts2);
        scatterLanes(omega, s.node + p, integral * inverseLength);
    }
}

// 6. The nodes in regime A or B (status < 0, only within the cut) with the per-node code.
DROPLETFIBER_ALWAYS_INLINE void exactOmegas(const PathWeight& path, double inverseLength,
                                            const double* lambdaM, const double* d0Squared, const Stages& s,
                                            double* omega)
{
    for (std::size_t n = 0; n < s.count; ++n)
    {
        if (s.status[n] < 0.0)
        {
            omega[n] = path.integralAlongPath(lambdaM[n], d0Squared[n]) * inverseLength;
        }
    }
}

// PathWeightBatch::omegas with its working memory: values 11 count doubles, indices
// 8 count + laneCount.
void omegasInLanes(const PathWeight& path, const double* lambdaM, const double* d0Squared, double* omega,
                   std::size_t count, double* values, std::uint32_t* indices)
{
    const PathIntegralClosedForm closedForm = closedFormOf(path);
    const double inverseLength = 1.0 / path.length();
    const Stages stages = stagesIn(count, values, indices);
    classifyNodes(closedForm, path.cutoffSquared(), lambdaM, d0Squared, omega, stages);
    const std::size_t packed = packClosedFormNodes(stages);
    if (packed > 0)
    {
        exponentialsInPlace(stages, packed);
        erfcScaledPartsOfEnds(stages, packed);
        closedFormOmegas(closedForm, inverseLength, stages, packed, omega);
    }
    exactOmegas(path, inverseLength, lambdaM, d0Squared, stages, omega);
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
    static const bool supported = []
    {
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

void PathWeightBatch::omegas(const PathWeight& path, const double* lambdaM, const double* d0Squared,
                             double* omega, std::size_t count)
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

const double* PathWeightBatch::boxOmegas(const PathWeight& path, const Eigen::Vector3d& start,
                                         const double* x, const double* y, const double* z,
                                         const std::array<int, 3>& lo, const std::array<int, 3>& hi)
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
