// NodeWeightBatch: the stages of PathWeight::integralAlongPath as loops over a parcel's
// nodes (see the header). Every formula is copied from PathWeight.hpp/.cpp in the same
// order of operations; keep the two in step (NodeWeightBatchTest compares the bits).
#include "grid/NodeWeightBatch.hpp"

#include "grid/ScaledErfc.hpp"

#include <algorithm>
#include <cmath>

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

} // namespace

void NodeWeightBatch::start(const PathWeight& path, std::size_t nodeCount)
{
    path_ = &path;
    added_ = 0;
    candidates_ = 0;
    growTo(omega_, nodeCount);
    for (auto* v : {&candidateSlot_, &slot_, &twoSided_})
    {
        growTo(*v, nodeCount);
    }
    for (auto* v : {&byRange_[0], &byRange_[1], &byRange_[2]})
    {
        growTo(*v, 2 * nodeCount);
    }
    for (auto* v : {&argument_, &numerator_, &denominator_})
    {
        growTo(*v, 2 * nodeCount);
    }
    for (auto* v : {&lambdaM_, &d0Squared_, &closedD0Squared_, &u1_, &u2_, &width_, &g1_, &g2_, &ends_})
    {
        growTo(*v, nodeCount);
    }
    growTo(clipped1_, nodeCount);
    growTo(clipped2_, nodeCount);
}

void NodeWeightBatch::add(const Eigen::Vector3d& offset)
{
    addRow(&offset.x(), 1, 0.0, offset.y(), offset.z());
}

void NodeWeightBatch::addRow(const double* x, std::size_t count, double startX, double offsetY, double offsetZ)
{
    const PathWeight& p = *path_;
    double* omega = omega_.data() + added_;
    if (p.stationary_)
    {
        for (std::size_t i = 0; i < count; ++i)
        {
            omega[i] = p.omegaFromOffset(Eigen::Vector3d(x[i] - startX, offsetY, offsetZ));
        }
        added_ += count;
        return;
    }
    // Stage 1: projection on the path line and the reach test of omegaFromOffset; nodes
    // that pass are appended to the candidates (written always, counted when they pass).
    const Eigen::Vector3d direction = p.direction_;
    const double length = p.length_;
    const double cutoffSquared = p.cutoffSquared_;
    const double reachSquared = p.reachSquared_;
    std::size_t* slot = candidateSlot_.data();
    double* lambdaMs = lambdaM_.data();
    double* d0Squareds = d0Squared_.data();
    std::size_t n = candidates_;
    for (std::size_t i = 0; i < count; ++i)
    {
        const Eigen::Vector3d offset(x[i] - startX, offsetY, offsetZ);
        const double lambdaM = direction.dot(offset);
        const double d0Squared = (offset - lambdaM * direction).squaredNorm();
        const double beyond = lambdaM <= 0.0 ? lambdaM : (lambdaM >= length ? length - lambdaM : 0.0);
        const bool within = (d0Squared < cutoffSquared) & (beyond * beyond < reachSquared - d0Squared);
        omega[i] = 0.0;
        slot[n] = added_ + i;
        lambdaMs[n] = lambdaM;
        d0Squareds[n] = d0Squared;
        n += static_cast<std::size_t>(within);
    }
    candidates_ = n;
    added_ += count;
}

const double* NodeWeightBatch::evaluate()
{
    const PathWeight& p = *path_;
    if (p.stationary_)
    {
        return omega_.data();
    }
    const double gamma = p.kernel_.gamma();
    const double edgeValue = p.kernel_.edgeValue();
    const double length = p.length_;
    const double reachSquared = p.reachSquared_;
    const double sqrtGamma = p.sqrtGamma_;
    const double inverseLength = p.inverseLength_;
    double* omega = omega_.data();

    // Stage 2: interval and regime, as integralAlongPath up to regime C (the early exit
    // there cannot trigger: stage 1 made the same comparison).
    std::size_t closed = 0;
    std::size_t twoSided = 0;
    for (std::size_t c = 0; c < candidates_; ++c)
    {
        const double lambdaM = lambdaM_[c];
        const double d0Squared = d0Squared_[c];
        const double halfChordSquared = reachSquared - d0Squared;
        const double toEnd = length - lambdaM;
        const bool startWithin = lambdaM * lambdaM < halfChordSquared;
        const bool endWithin = toEnd * toEnd < halfChordSquared;
        double lambda1 = 0.0;
        double lambda2 = length;
        bool clipped1 = false;
        bool clipped2 = false;
        double halfChord = 0.0;
        if (!startWithin || !endWithin)
        {
            halfChord = std::sqrt(halfChordSquared);
            if (!startWithin && lambdaM - halfChord > 0.0)
            {
                lambda1 = lambdaM - halfChord;
                clipped1 = true;
            }
            if (!endWithin && lambdaM + halfChord < length)
            {
                lambda2 = lambdaM + halfChord;
                clipped2 = true;
            }
            if (!(lambda2 > lambda1))
            {
                continue; // the chord misses the path: omega stays 0
            }
        }
        const double width = lambda2 - lambda1;
        const double u1 = clipped1 ? -halfChord : -lambdaM;
        const double u2 = clipped2 ? halfChord : toEnd;
        const bool spansClosest = (u1 <= 0.0) & (u2 >= 0.0);
        const double uNearest = std::min(std::abs(u1), std::abs(u2)) * static_cast<double>(!spansClosest);
        const double qMax = gamma * (halfChordSquared - uNearest * uNearest);
        const double xCentre = sqrtGamma * (0.5 * (lambda1 + lambda2) - lambdaM);
        const double xHalf = sqrtGamma * 0.5 * width;
        if (qMax < 0.25 || xHalf * (1.0 + std::abs(xCentre)) <= 0.5)
        {
            // Regimes A and B: the exact scalar code.
            omega[candidateSlot_[c]] = p.integralAlongPath(lambdaM, d0Squared) * inverseLength;
            continue;
        }
        slot_[closed] = candidateSlot_[c];
        closedD0Squared_[closed] = d0Squared;
        u1_[closed] = u1;
        u2_[closed] = u2;
        width_[closed] = width;
        clipped1_[closed] = clipped1;
        clipped2_[closed] = clipped2;
        twoSided_[twoSided] = closed;
        twoSided += static_cast<std::size_t>((sqrtGamma * u1 < 0.0) & (sqrtGamma * u2 > 0.0));
        ++closed;
    }

    // Stage 3: the Gaussians at the ends.
    for (std::size_t c = 0; c < closed; ++c)
    {
        const double d0Squared = closedD0Squared_[c];
        const double u1 = u1_[c];
        const double u2 = u2_[c];
        g1_[c] = clipped1_[c] ? edgeValue : std::exp(-gamma * (d0Squared + u1 * u1));
        g2_[c] = clipped2_[c] ? edgeValue : std::exp(-gamma * (d0Squared + u2 * u2));
    }
    // Stage 4: scaled erfc at both ends, the arguments sorted by Cody's range first so
    // that each range is one loop without the range branch.
    double* numerator = numerator_.data();
    double* denominator = denominator_.data();
    double* argument = argument_.data();
    std::size_t inRange[3] = {0, 0, 0};
    for (std::size_t a = 0; a < 2 * closed; ++a)
    {
        const double x = std::abs(sqrtGamma * (a & 1 ? u2_[a >> 1] : u1_[a >> 1]));
        argument[a] = x;
        const int range = erfcScaledRange(x);
        byRange_[range][inRange[range]++] = a;
    }
    for (std::size_t k = 0; k < inRange[0]; ++k)
    {
        const std::size_t a = byRange_[0][k];
        const Fraction f = erfcScaledSmall(argument[a]);
        numerator[a] = f.numerator;
        denominator[a] = f.denominator;
    }
    for (std::size_t k = 0; k < inRange[1]; ++k)
    {
        const std::size_t a = byRange_[1][k];
        const Fraction f = erfcScaledMedium(argument[a]);
        numerator[a] = f.numerator;
        denominator[a] = f.denominator;
    }
    for (std::size_t k = 0; k < inRange[2]; ++k)
    {
        const std::size_t a = byRange_[2][k];
        const Fraction f = erfcScaledLarge(argument[a]);
        numerator[a] = f.numerator;
        denominator[a] = f.denominator;
    }
    // Stage 5: the end terms with their signs, and omega as for a one-sided node.
    // integralAlongPath's three cases of regime C are
    //   sqrt(pi)/2 [s1 g1 erfcScaled(|x1|) + s2 g2 erfcScaled(|x2|)] (+ sqrt(pi) exp(-gamma d0^2)
    // when two-sided), s1 = +1 iff x1 >= 0, s2 = +1 iff x2 <= 0: one formula, no branch on
    // the case. The signs are exact and a + (-b) = a - b, (-a) + b = b - a in IEEE
    // arithmetic, so the bits are those of the three cases there.
    const double inverseSqrtGamma = p.inverseSqrtGamma_;
    for (std::size_t c = 0; c < closed; ++c)
    {
        const double s1 = 1.0 - 2.0 * static_cast<double>(sqrtGamma * u1_[c] < 0.0);
        const double s2 = 1.0 - 2.0 * static_cast<double>(sqrtGamma * u2_[c] > 0.0);
        const double n1 = numerator[2 * c], d1 = denominator[2 * c];
        const double n2 = numerator[2 * c + 1], d2 = denominator[2 * c + 1];
        const double ends = halfSqrtPi * (s1 * g1_[c] * n1 * d2 + s2 * g2_[c] * n2 * d1) / (d1 * d2);
        ends_[c] = ends;
        omega[slot_[c]] = (ends * inverseSqrtGamma - edgeValue * width_[c]) * inverseLength;
    }
    // Stage 6: two-sided nodes add the whole Gaussian.
    for (std::size_t t = 0; t < twoSided; ++t)
    {
        const std::size_t c = twoSided_[t];
        const double gaussian = 2.0 * halfSqrtPi * std::exp(-gamma * closedD0Squared_[c]) + ends_[c];
        omega[slot_[c]] = (gaussian * inverseSqrtGamma - edgeValue * width_[c]) * inverseLength;
    }
    return omega;
}

} // namespace dropletFiber
