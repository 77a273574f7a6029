// NodeWeightBatch: classification of nodes by regime, then one loop per regime (see the
// header). Every formula is copied from PathWeight::integralAlongPath in the same order
// of operations; keep the two in step.
#include "grid/NodeWeightBatch.hpp"

#include "grid/ScaledErfc.hpp"

#include <algorithm>
#include <cstdint>

#include <emmintrin.h>

namespace dropletFiber
{

namespace
{

constexpr double halfSqrtPi = 0.88622692545275801365; // sqrt(pi) / 2, as in PathWeight.cpp

template <class T>
void growTo(std::vector<T>& v, std::size_t n)
{
    if (v.size() < n)
    {
        v.resize(n);
    }
}

// Comparison masks and selects in SSE2 registers: the classification must not branch,
// and GCC turns bool conditions and ternaries on doubles into jumps.
struct Mask
{
    __m128d bits;
};
inline Mask operator&(Mask a, Mask b) { return {_mm_and_pd(a.bits, b.bits)}; }
inline Mask operator|(Mask a, Mask b) { return {_mm_or_pd(a.bits, b.bits)}; }
inline Mask operator~(Mask a) { return {_mm_xor_pd(a.bits, _mm_castsi128_pd(_mm_set1_epi32(-1)))}; }
inline Mask less(double a, double b) { return {_mm_cmplt_sd(_mm_set_sd(a), _mm_set_sd(b))}; }
inline Mask lessEqual(double a, double b) { return {_mm_cmple_sd(_mm_set_sd(a), _mm_set_sd(b))}; }
inline double select(Mask m, double a, double b)
{
    return _mm_cvtsd_f64(_mm_or_pd(_mm_and_pd(m.bits, _mm_set_sd(a)), _mm_andnot_pd(m.bits, _mm_set_sd(b))));
}
inline Mask select(Mask m, Mask a, Mask b) { return (m & a) | (~m & b); }
inline std::size_t isSet(Mask m) { return static_cast<std::size_t>(_mm_movemask_pd(m.bits) & 1); }

} // namespace

void NodeWeightBatch::start(const PathWeight& path, std::size_t nodeCount)
{
    path_ = &path;
    added_ = 0;
    oneSidedCount_ = 0;
    twoSidedCount_ = 0;
    rareCount_ = 0;
    growTo(omega_, nodeCount);
    growTo(oneSided_, nodeCount);
    growTo(twoSided_, nodeCount);
    growTo(rare_, nodeCount);
    growTo(argument_, 2 * nodeCount);
    growTo(numerator_, 2 * nodeCount);
    growTo(denominator_, 2 * nodeCount);
    for (auto& list : byRange_)
    {
        growTo(list, 2 * nodeCount);
    }
}

NodeWeightBatch::Cursor NodeWeightBatch::cursor() const
{
    const PathWeight& p = *path_;
    Cursor c;
    c.direction = p.direction_;
    c.gamma = p.kernel_.gamma();
    c.length = p.length_;
    c.reachSquared = p.reachSquared_;
    c.cutoffSquared = p.cutoffSquared_;
    c.sqrtGamma = p.sqrtGamma_;
    c.omega = const_cast<double*>(omega_.data());
    c.oneSided = const_cast<ClosedFormNode*>(oneSided_.data()) + oneSidedCount_;
    c.twoSided = const_cast<ClosedFormNode*>(twoSided_.data()) + twoSidedCount_;
    c.rare = const_cast<RareNode*>(rare_.data()) + rareCount_;
    return c;
}

void NodeWeightBatch::store(const Cursor& c)
{
    oneSidedCount_ = static_cast<std::size_t>(c.oneSided - oneSided_.data());
    twoSidedCount_ = static_cast<std::size_t>(c.twoSided - twoSided_.data());
    rareCount_ = static_cast<std::size_t>(c.rare - rare_.data());
}

inline void NodeWeightBatch::classify(Cursor& cur, std::size_t slot, const Eigen::Vector3d& offset)
{
    const double gamma = cur.gamma;
    const double length = cur.length;
    // As PathWeight::omegaFromOffset.
    const double lambdaM = cur.direction.dot(offset);
    const double d0Squared = (offset - lambdaM * cur.direction).squaredNorm();
    // As integralAlongPath, with every choice a mask (plain C++ conditions compile to
    // branches here). The early exit there (reach circle wholly before the start or after
    // the end of the path) is the same as: the node is at least reach from the segment.
    const double halfChordSquared = cur.reachSquared - d0Squared;
    const double toEnd = length - lambdaM;
    const Mask startWithin = less(lambdaM * lambdaM, halfChordSquared);
    const Mask endWithin = less(toEnd * toEnd, halfChordSquared);
    const Mask missesPath = (lessEqual(lambdaM, 0.0) & ~startWithin) | (lessEqual(length, lambdaM) & ~endWithin);
    const double halfChord = std::sqrt(std::max(halfChordSquared, 0.0));
    const Mask clipped1 = less(0.0, lambdaM - halfChord) & ~startWithin;
    const Mask clipped2 = less(lambdaM + halfChord, length) & ~endWithin;
    const double lambda1 = select(clipped1, lambdaM - halfChord, 0.0);
    const double lambda2 = select(clipped2, lambdaM + halfChord, length);
    const Mask inReach = less(d0Squared, cur.cutoffSquared) & less(lambda1, lambda2) & ~missesPath;

    const double width = lambda2 - lambda1;
    const double u1 = select(clipped1, -halfChord, -lambdaM);
    const double u2 = select(clipped2, halfChord, toEnd);
    const double absU1 = std::abs(u1);
    const double absU2 = std::abs(u2);
    const double uNearest
        = select(lessEqual(u1, 0.0) & lessEqual(0.0, u2), 0.0, select(less(absU2, absU1), absU2, absU1));
    const double qMax = gamma * (halfChordSquared - uNearest * uNearest);
    const double xCentre = cur.sqrtGamma * (0.5 * (lambda1 + lambda2) - lambdaM);
    const double xHalf = cur.sqrtGamma * 0.5 * width;
    // Regimes A (edge quadrature) and B (Taylor): the exact scalar code.
    const Mask rare = less(qMax, 0.25) | lessEqual(xHalf * (1.0 + std::abs(xCentre)), 0.5);
    const double x1 = cur.sqrtGamma * u1;
    const double x2 = cur.sqrtGamma * u2;
    const Mask after = lessEqual(0.0, x1);
    const Mask oneSided = after | lessEqual(x2, 0.0);

    cur.omega[slot] = 0.0;
    *cur.rare = RareNode{slot, lambdaM, d0Squared};
    cur.rare += isSet(inReach & rare);
    // One record per node, written once: to the one-sided or the two-sided list (a node
    // of neither class is written past the end of the one-sided list and overwritten).
    // One-sided: near end first, erfc arguments as in integralAlongPath (after: x1, x2;
    // before: -x2, -x1). Two-sided: -x1, x2.
    const Mask closedForm = inReach & ~rare;
    const std::size_t two = isSet(closedForm & ~oneSided);
    const std::size_t one = isSet(closedForm & oneSided);
    ClosedFormNode& c = two ? *cur.twoSided : *cur.oneSided;
    const Mask swap = ~after & oneSided;
    c.slot = slot;
    c.d0Squared = d0Squared;
    c.uFirst = select(swap, u2, u1);
    c.uSecond = select(swap, u1, u2);
    c.width = width;
    c.xFirst = select(after, x1, -select(oneSided, x2, x1));
    c.xSecond = select(swap, -x1, x2);
    c.clippedFirst = isSet(select(swap, clipped2, clipped1));
    c.clippedSecond = isSet(select(swap, clipped1, clipped2));
    cur.oneSided += one;
    cur.twoSided += two;
}

void NodeWeightBatch::add(const Eigen::Vector3d& offset)
{
    const std::size_t slot = added_++;
    if (path_->stationary_)
    {
        omega_[slot] = path_->omegaFromOffset(offset);
        return;
    }
    Cursor c = cursor();
    classify(c, slot, offset);
    store(c);
}

void NodeWeightBatch::addRow(const double* x, std::size_t count, double startX, double offsetY, double offsetZ)
{
    if (path_->stationary_)
    {
        for (std::size_t i = 0; i < count; ++i)
        {
            omega_[added_++] = path_->omegaFromOffset(Eigen::Vector3d(x[i] - startX, offsetY, offsetZ));
        }
        return;
    }
    Cursor c = cursor();
    for (std::size_t i = 0; i < count; ++i)
    {
        classify(c, added_ + i, Eigen::Vector3d(x[i] - startX, offsetY, offsetZ));
    }
    added_ += count;
    store(c);
}

void NodeWeightBatch::evaluateScaledErfc(std::size_t count)
{
    // Sort the argument indices by range (compaction), then one loop per range.
    std::size_t inRange[3] = {0, 0, 0};
    for (std::size_t a = 0; a < count; ++a)
    {
        const int range = erfcScaledRange(argument_[a]);
        byRange_[range][inRange[range]++] = a;
    }
    for (std::size_t n = 0; n < inRange[0]; ++n)
    {
        const std::size_t a = byRange_[0][n];
        const Fraction f = erfcScaledSmall(argument_[a]);
        numerator_[a] = f.numerator;
        denominator_[a] = f.denominator;
    }
    for (std::size_t n = 0; n < inRange[1]; ++n)
    {
        const std::size_t a = byRange_[1][n];
        const Fraction f = erfcScaledMedium(argument_[a]);
        numerator_[a] = f.numerator;
        denominator_[a] = f.denominator;
    }
    for (std::size_t n = 0; n < inRange[2]; ++n)
    {
        const std::size_t a = byRange_[2][n];
        const Fraction f = erfcScaledLarge(argument_[a]);
        numerator_[a] = f.numerator;
        denominator_[a] = f.denominator;
    }
}

const double* NodeWeightBatch::evaluate()
{
    if (path_->stationary_)
    {
        return omega_.data();
    }
    const PathWeight& p = *path_;
    const double gamma = p.kernel_.gamma();
    const double edgeValue = p.kernel_.edgeValue();

    // erfc arguments: one-sided x_near, x_far (|x|, both >= 0); two-sided -x1, x2.
    const std::size_t nOne = oneSidedCount_;
    const std::size_t nTwo = twoSidedCount_;
    for (std::size_t n = 0; n < nOne; ++n)
    {
        argument_[2 * n] = oneSided_[n].xFirst;
        argument_[2 * n + 1] = oneSided_[n].xSecond;
    }
    for (std::size_t n = 0; n < nTwo; ++n)
    {
        argument_[2 * (nOne + n)] = twoSided_[n].xFirst;
        argument_[2 * (nOne + n) + 1] = twoSided_[n].xSecond;
    }
    evaluateScaledErfc(2 * (nOne + nTwo));

    const double inverseSqrtGamma = p.inverseSqrtGamma_;
    const double inverseLength = p.inverseLength_;
    for (std::size_t n = 0; n < nOne; ++n)
    {
        const ClosedFormNode& c = oneSided_[n];
        const double gNear = c.clippedFirst ? edgeValue : std::exp(-gamma * (c.d0Squared + c.uFirst * c.uFirst));
        const double gFar = c.clippedSecond ? edgeValue : std::exp(-gamma * (c.d0Squared + c.uSecond * c.uSecond));
        const double nearNumerator = numerator_[2 * n], nearDenominator = denominator_[2 * n];
        const double farNumerator = numerator_[2 * n + 1], farDenominator = denominator_[2 * n + 1];
        const double gaussian = halfSqrtPi
            * (gNear * nearNumerator * farDenominator - gFar * farNumerator * nearDenominator)
            / (nearDenominator * farDenominator);
        omega_[c.slot] = (gaussian * inverseSqrtGamma - edgeValue * c.width) * inverseLength;
    }
    for (std::size_t n = 0; n < nTwo; ++n)
    {
        const ClosedFormNode& c = twoSided_[n];
        const double g1 = c.clippedFirst ? edgeValue : std::exp(-gamma * (c.d0Squared + c.uFirst * c.uFirst));
        const double g2 = c.clippedSecond ? edgeValue : std::exp(-gamma * (c.d0Squared + c.uSecond * c.uSecond));
        const std::size_t a = 2 * (nOne + n);
        const double startNumerator = numerator_[a], startDenominator = denominator_[a];
        const double endNumerator = numerator_[a + 1], endDenominator = denominator_[a + 1];
        const double gaussian = 2.0 * halfSqrtPi * std::exp(-gamma * c.d0Squared)
            - halfSqrtPi * (g1 * startNumerator * endDenominator + g2 * endNumerator * startDenominator)
                / (startDenominator * endDenominator);
        omega_[c.slot] = (gaussian * inverseSqrtGamma - edgeValue * c.width) * inverseLength;
    }
    for (std::size_t n = 0; n < rareCount_; ++n)
    {
        const RareNode& r = rare_[n];
        omega_[r.slot] = p.integralAlongPath(r.lambdaM, r.d0Squared) * inverseLength;
    }
    return omega_.data();
}

} // namespace dropletFiber
