#include "grid/PathWeight.hpp"

#include "grid/GaussLegendre.hpp"
#include "grid/ScaledErfc.hpp"

#include <cmath>

namespace dropletFiber
{

namespace
{

constexpr double halfSqrtPi = 0.88622692545275801365; // sqrt(pi) / 2

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
    double hermiteEven = 1.0;     // H_2m
    double hermiteOdd = twoX;     // H_2m+1
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

// The part [lambda1, lambda2] of the path [0, L] (along-path coordinate) within reach of a
// node that projects to lambdaM on the path line, where the reach circle cuts that line in
// a chord of half length h = sqrt(halfChordSquared) about lambdaM. An end of the interval
// that is not an end of the path lies on the reach circle (clipped), where the Gaussian is
// exactly exp(-a).
struct PathChord
{
    double lambda1 = 0.0;
    double lambda2 = 0.0;
    bool clipped1 = false;
    bool clipped2 = false;
    double halfChord = 0.0; // h, or 0 where not needed (both ends of the path within reach)
};

// False when the chord misses the path (nothing to integrate).
bool chordOnPath(double lambdaM, double halfChordSquared, double length, PathChord& chord)
{
    // An end of the path is within reach iff its offset from lambdaM is below h (compared
    // squared: no sqrt in the common case).
    const double toEnd = length - lambdaM;
    const bool startWithin = lambdaM * lambdaM < halfChordSquared;
    const bool endWithin = toEnd * toEnd < halfChordSquared;
    chord.lambda1 = 0.0;
    chord.lambda2 = length;
    if (startWithin && endWithin)
    {
        return true;
    }
    // The reach circle lies wholly before the start or after the end of the path
    // (5.6 of 37 calls per parcel): nothing to integrate, skip the square root.
    if ((!startWithin && lambdaM <= 0.0) || (!endWithin && lambdaM >= length))
    {
        return false;
    }
    chord.halfChord = std::sqrt(halfChordSquared);
    if (!startWithin && lambdaM - chord.halfChord > 0.0)
    {
        chord.lambda1 = lambdaM - chord.halfChord;
        chord.clipped1 = true;
    }
    if (!endWithin && lambdaM + chord.halfChord < length)
    {
        chord.lambda2 = lambdaM + chord.halfChord;
        chord.clipped2 = true;
    }
    return chord.lambda2 > chord.lambda1; // else the chord misses the path
}

// Regime A, int phi dlambda over [u1, u2] (offsets from lambdaM) where the interval only
// grazes the edge of the support: the Gaussian and the constant of eq. 12 nearly cancel,
// so phi = exp(-a) expm1(q) is integrated pointwise; q is a quadratic of range <= 0.25
// here, so the 10-point rule is exact to round-off.
double grazingIntegral(double gamma, double edgeValue, double halfChord, double u1, double u2, double width)
{
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

// Regime C: exp(-gamma d0^2) int_{x1}^{x2} exp(-x^2) dx in the closed form of docs/model.md sec. 4,
// written with the kernel's Gaussians at the interval's ends, g_i = exp(-gamma (d0^2 + u_i^2))
// (exp(-a) where the end is on the reach circle), and erfcScaled(x) = exp(x^2) erfc(x):
//   0 <= x1 < x2:  sqrt(pi)/2 [g1 erfcScaled(x1) - g2 erfcScaled(x2)]
//   x1 < x2 <= 0:  sqrt(pi)/2 [g2 erfcScaled(-x2) - g1 erfcScaled(-x1)]
//   x1 < 0 < x2:   sqrt(pi) exp(-gamma d0^2) - sqrt(pi)/2 [g1 erfcScaled(-x1) + g2 erfcScaled(x2)]
// Outside regime B the two terms differ by a factor >~ 1.5 (no cancellation).
double closedFormGaussian(double gamma, double d0Squared, double x1, double x2, double g1, double g2)
{
    if (x1 >= 0.0 || x2 <= 0.0)
    {
        // Both ends on one side of the closest point: the nearer end minus the farther one.
        const bool after = x1 >= 0.0;
        const Fraction nearEnd = erfcScaledFraction(after ? x1 : -x2);
        const Fraction farEnd = erfcScaledFraction(after ? x2 : -x1);
        const double gNear = after ? g1 : g2;
        const double gFar = after ? g2 : g1;
        return halfSqrtPi
            * (gNear * nearEnd.numerator * farEnd.denominator - gFar * farEnd.numerator * nearEnd.denominator)
            / (nearEnd.denominator * farEnd.denominator);
    }
    const Fraction start = erfcScaledFraction(-x1);
    const Fraction end = erfcScaledFraction(x2);
    return 2.0 * halfSqrtPi * std::exp(-gamma * d0Squared)
        - halfSqrtPi * (g1 * start.numerator * end.denominator + g2 * end.numerator * start.denominator)
        / (start.denominator * end.denominator);
}

} // namespace

PathWeight::PathWeight(const ParcelKernel& kernel, const Eigen::Vector3d& start,
                       const Eigen::Vector3d& displacement)
    : kernel_(kernel), start_(start), halfDisplacement_(0.5 * displacement)
{
    reachSquared_ = kernel.reach() * kernel.reach();
    cutoffSquared_ = reachSquared_;
    sqrtGamma_ = std::sqrt(kernel.gamma());
    inverseSqrtGamma_ = 1.0 / sqrtGamma_;
    length_ = displacement.norm();
    stationary_ = !(length_ > stationaryFraction * kernel.reach());
    if (!stationary_)
    {
        inverseLength_ = 1.0 / length_;
        direction_ = displacement * inverseLength_;
    }
}

double PathWeight::integralAlongPath(double lambdaM, double d0Squared) const
{
    const double gamma = kernel_.gamma();
    const double edgeValue = kernel_.edgeValue();
    const double halfChordSquared = reachSquared_ - d0Squared;
    PathChord chord;
    if (!chordOnPath(lambdaM, halfChordSquared, length_, chord))
    {
        return 0.0;
    }
    // Width from the lambdas (exact for an unclipped path; u2 - u1 would cancel for L -> 0).
    const double width = chord.lambda2 - chord.lambda1;
    const double u1 = chord.clipped1 ? -chord.halfChord : -lambdaM;
    const double u2 = chord.clipped2 ? chord.halfChord : length_ - lambdaM;

    // Largest q = gamma (h^2 - u^2) on the interval; phi = exp(-a) expm1(q).
    const double uNearest = (u1 <= 0.0 && u2 >= 0.0) ? 0.0 : std::min(std::abs(u1), std::abs(u2));
    const double qMax = gamma * (halfChordSquared - uNearest * uNearest);
    if (qMax < 0.25)
    {
        // Regime A: the interval only grazes the edge of the support.
        const double halfChord = chord.halfChord == 0.0 ? std::sqrt(halfChordSquared) : chord.halfChord;
        return grazingIntegral(gamma, edgeValue, halfChord, u1, u2, width);
    }

    // From here on qMax >= 0.25: the mean of expm1(q) is at least qMax / 2 (q is concave),
    // so subtracting the constant term loses at most one digit.
    const double xCentre = sqrtGamma_ * (0.5 * (chord.lambda1 + chord.lambda2) - lambdaM);
    const double xHalf = sqrtGamma_ * 0.5 * width;
    if (xHalf * (1.0 + std::abs(xCentre)) <= 0.5)
    {
        // Regime B: short interval in x (includes L -> 0): Taylor series about the middle,
        // one exponential, no erf difference that would cancel.
        const double gaussian = std::exp(-(gamma * d0Squared + xCentre * xCentre))
            * gaussianTaylorSum(xCentre, xHalf) * inverseSqrtGamma_;
        return gaussian - edgeValue * width;
    }

    // Regime C: the closed form of docs/model.md sec. 4.
    const double g1 = chord.clipped1 ? edgeValue : std::exp(-gamma * (d0Squared + u1 * u1));
    const double g2 = chord.clipped2 ? edgeValue : std::exp(-gamma * (d0Squared + u2 * u2));
    const double gaussian = closedFormGaussian(gamma, d0Squared, sqrtGamma_ * u1, sqrtGamma_ * u2, g1, g2);
    return gaussian * inverseSqrtGamma_ - edgeValue * width;
}

} // namespace dropletFiber
