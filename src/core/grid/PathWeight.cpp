#include "grid/PathWeight.hpp"

#include "grid/GaussLegendre.hpp"
#include "grid/Lanes.hpp"

#include <cmath>

namespace dropletFiber
{

namespace
{

// Paths shorter than this fraction of the reach are taken as a point (error of order
// (gamma L^2)^2, far below round-off).
constexpr double stationaryFraction = 1e-12;

// int_{xc-h}^{xc+h} exp(-x^2) dx = exp(-xc^2) * S with the Taylor series about the
// midpoint: S = sum_m 2 h^(2m+1) / (2m+1)! * H_2m(xc) (H_n: Hermite polynomials,
// d^n/dx^n exp(-x^2) = (-1)^n H_n(x) exp(-x^2)). Used for h (1 + |xc|) <= 0.5, where the
// terms fall at least ~ 0.25^m / (2m+1)!, so 12 terms are beyond round-off.
double gaussianTaylorSum(double xc, double h)
{
    const double h2 = h * h;
    const double twoX = 2.0 * xc;
    double coefficient = 2.0 * h; // 2 h^(2m+1) / (2m+1)!
    double hermiteEven = 1.0;      // H_2m
    double hermiteOdd = twoX;      // H_2m+1
    double sum = coefficient;
    for (int m = 1; m <= 12; ++m)
    {
        const double nextEven = twoX * hermiteOdd - 2.0 * (2 * m - 1) * hermiteEven;
        const double nextOdd = twoX * nextEven - 2.0 * (2 * m) * hermiteOdd;
        hermiteEven = nextEven;
        hermiteOdd = nextOdd;
        coefficient *= h2 / ((2.0 * m) * (2.0 * m + 1.0));
        const double term = coefficient * hermiteEven;
        sum += term;
        // Stop when this term and the size of the next are negligible (the bound uses
        // |H_2m+1| too, so that a term that is small only because xc sits near a zero of
        // H_2m does not end the series early).
        if (coefficient * (std::abs(hermiteEven) + h * std::abs(hermiteOdd)) < 1e-18 * std::abs(sum))
        {
            break;
        }
    }
    return sum;
}

} // namespace

PathWeight::PathWeight(const ParcelKernel& kernel, const Eigen::Vector3d& start, const Eigen::Vector3d& displacement)
    : kernel_(kernel), start_(start), halfDisplacement_(0.5 * displacement)
{
    reachSquared_ = kernel.reach() * kernel.reach();
    sqrtGamma_ = std::sqrt(kernel.gamma());
    inverseSqrtGamma_ = 1.0 / sqrtGamma_;
    length_ = displacement.norm();
    stationary_ = !(length_ > stationaryFraction * kernel.reach());
    if (!stationary_)
    {
        inverseLength_ = 1.0 / length_;
        direction_ = displacement * inverseLength_;
    }
    closedForm_.length = length_;
    closedForm_.reachSquared = reachSquared_;
    closedForm_.gamma = kernel.gamma();
    closedForm_.sqrtGamma = sqrtGamma_;
    closedForm_.inverseSqrtGamma = inverseSqrtGamma_;
    closedForm_.edgeExponent = kernel.edgeExponent();
    closedForm_.edgeValue = kernel.edgeValue();
}

double PathWeight::integralAlongPath(double lambdaM, double d0Squared) const
{
    bool needsExact = false;
    const double integral = closedForm_(lambdaM, d0Squared, needsExact);
    return needsExact ? exactIntegral(lambdaM, d0Squared) : integral;
}

namespace
{

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

// Evaluates one interval of erfcScaledParts for the listed ends.
template <class Interval>
void erfcScaledPartsAt(const std::uint32_t* list, std::size_t count, const double* x, double* numerators,
                       double* denominators, Interval interval)
{
    for (std::size_t e = 0; e < count; e += laneCount)
    {
        const FractionOf<Lanes> parts = interval(magnitude(gatherLanes(x, list + e)));
        scatterLanes(numerators, list + e, parts.numerator);
        scatterLanes(denominators, list + e, parts.denominator);
    }
}

} // namespace

void PathWeight::omegas(const double* lambdaM, const double* d0Squared, double* omega, std::size_t count,
                        Scratch& scratch) const
{
    // The stages of PathIntegralClosedForm as separate short loops, so that the processor
    // overlaps many nodes (the whole formula is a dependency chain of ~700 instructions
    // per two nodes, longer than the reorder window), and so that the exponentials and
    // rational functions are evaluated only where needed:
    //  1. interval and regime of every node (lanes);
    //  2. the nodes in the closed-form regime are packed to the front (no branch);
    //  3. their three Gaussians (lanes);
    //  4. their two ends sorted by the interval of the scaled erfc, each list evaluated
    //     with its own rational function (lanes; one rational per end instead of three);
    //  5. the formula (lanes), written to the node's place;
    //  6. the ~1 node per parcel in regime A or B with the scalar code.
    const std::size_t ends = 2 * count;
    if (scratch.values.size() < 11 * count)
    {
        scratch.values.resize(11 * count);
        scratch.indices.resize(4 * ends + laneCount);
    }
    double* x = scratch.values.data();           // x1 of every node, then x2
    double* exponents = x + ends;                 // exponent0, 1, 2; then exp of them in place
    double* numerators = exponents + 3 * count;   // erfcScaledParts of |x1|, then |x2|
    double* denominators = numerators + ends;
    double* width = denominators + ends;
    double* status = width + count;
    std::uint32_t* node = scratch.indices.data(); // packed position -> node
    std::uint32_t* lists = node + count + laneCount;

    for (std::size_t n = 0; n < count; n += laneCount) // 1.
    {
        const PathIntegralClosedForm::Interval<Lanes> interval
            = closedForm_.interval(loadLanes(lambdaM + n), loadLanes(d0Squared + n));
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
        if (packed % laneCount != 0) // pad by repeating the last packed node
        {
            const std::size_t last = packed - 1;
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
            const std::size_t length = padToLanes(list, listLength[interval]);
            if (interval == 0)
            {
                erfcScaledPartsAt(list, length, x, numerators, denominators,
                                  [](Lanes v) { return erfcScaledPartsSmall(v); });
            }
            else if (interval == 1)
            {
                erfcScaledPartsAt(list, length, x, numerators, denominators,
                                  [](Lanes v) { return erfcScaledPartsMiddle(v); });
            }
            else
            {
                erfcScaledPartsAt(list, length, x, numerators, denominators,
                                  [](Lanes v) { return erfcScaledPartsLarge(v); });
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
            const Lanes integral = closedForm_.integral(interval, loadLanes(exponents + p), loadLanes(exponents + count + p),
                                                        loadLanes(exponents + 2 * count + p), parts1, parts2);
            scatterLanes(omega, node + p, integral * inverseLength_);
        }
    }
    for (std::size_t n = 0; n < count; ++n) // 6.
    {
        if (status[n] < 0.0)
        {
            omega[n] = exactIntegral(lambdaM[n], d0Squared[n]) * inverseLength_;
        }
    }
}

// The scalar regime choice of integralAlongPath with regimes A and B; the same interval
// and tests as PathIntegralClosedForm, written with branches (only ~1 node per parcel).
double PathWeight::exactIntegral(double lambdaM, double d0Squared) const
{
    const double gamma = kernel_.gamma();
    const double edgeValue = kernel_.edgeValue();
    // Half chord h of the reach circle on the path line: the node is within reach for
    // lambda in (lambdaM - h, lambdaM + h). An end of the path is within reach iff its
    // offset from lambdaM is below h (compared squared: no sqrt in the common case).
    const double halfChordSquared = reachSquared_ - d0Squared;
    const double toEnd = length_ - lambdaM;
    const bool startWithin = lambdaM * lambdaM < halfChordSquared;
    const bool endWithin = toEnd * toEnd < halfChordSquared;
    // Integration interval [lambda1, lambda2]; an end that is not an end of the path lies
    // on the reach circle (clipped), where the Gaussian is exactly exp(-a).
    double lambda1 = 0.0;
    double lambda2 = length_;
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
        if (!endWithin && lambdaM + halfChord < length_)
        {
            lambda2 = lambdaM + halfChord;
            clipped2 = true;
        }
        if (!(lambda2 > lambda1))
        {
            return 0.0; // the chord misses the path
        }
    }
    // Width from the lambdas (exact for an unclipped path; u2 - u1 would cancel for L -> 0).
    const double width = lambda2 - lambda1;
    const double u1 = clipped1 ? -halfChord : -lambdaM;
    const double u2 = clipped2 ? halfChord : toEnd;

    // Largest q = gamma (h^2 - u^2) on the interval; phi = exp(-a) expm1(q).
    const double uNearest = (u1 <= 0.0 && u2 >= 0.0) ? 0.0 : std::min(std::abs(u1), std::abs(u2));
    const double qMax = gamma * (halfChordSquared - uNearest * uNearest);

    if (qMax < 0.25)
    {
        // Regime A: the interval only grazes the edge of the support. The Gaussian and the
        // constant of eq. 12 nearly cancel, so integrate phi = exp(-a) expm1(q) pointwise;
        // q is a quadratic of range <= 0.25 here, so the 10-point rule is exact to round-off.
        if (halfChord == 0.0)
        {
            halfChord = std::sqrt(halfChordSquared);
        }
        const GaussLegendreRule& rule = gaussLegendre();
        const double centre = 0.5 * (u1 + u2);
        const double half = 0.5 * width;
        double sum = 0.0;
        for (int i = 0; i < GaussLegendreRule::order; ++i)
        {
            const double u = std::abs(centre + half * rule.node[i]);
            sum += rule.weight[i] * std::expm1(gamma * (halfChord - u) * (halfChord + u));
        }
        return edgeValue * half * sum;
    }

    // From here on qMax >= 0.25: the mean of expm1(q) is at least qMax / 2 (q is concave),
    // so subtracting the constant term loses at most one digit.
    const double xCentre = sqrtGamma_ * (0.5 * (lambda1 + lambda2) - lambdaM);
    const double xHalf = sqrtGamma_ * 0.5 * width;
    if (xHalf * (1.0 + std::abs(xCentre)) <= 0.5)
    {
        // Regime B: short interval in x (includes L -> 0): Taylor series about the middle,
        // one exponential, no erf difference that would cancel.
        const double gaussian
            = std::exp(-(gamma * d0Squared + xCentre * xCentre)) * gaussianTaylorSum(xCentre, xHalf) * inverseSqrtGamma_;
        return gaussian - edgeValue * width;
    }

    // Regime C (not reached: PathIntegralClosedForm makes the same regime choice with the
    // same operations, and sends only A and B here).
    bool needsExact = false;
    return closedForm_(lambdaM, d0Squared, needsExact);
}

} // namespace dropletFiber
