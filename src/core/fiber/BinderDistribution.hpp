// BinderDistribution: how the captured binder lies along the fibers (docs/model.md sec. 3,
// discrete hits), over all fiber length, segment by segment (sigma_j = captured mass of
// segment j / its rest length l_j, L = sum l_j):
//     bare fraction    sum of l_j with no captured mass / L
//     mean sigma       sum m_j / L                                  kg/m
//     CoV of sigma     sqrt(sum l_j (sigma_j - mean)^2 / L) / mean   (length-weighted)
//     hits per length  sum of the segments' hits / L                1/m
// and the first three for the expected mode's mass on the same fibers (segmentExpectedMass:
// the mass the samples were granted; in expected mode the captured mass itself), so that
// both modes' distributions can be compared.
// The sums add up over fibers and processors (BinderSums::add, then the figures once); a
// computed fiber standing for N physical ones (Fiber::represents) counts N times (but its
// segments once: their count is the computed resolution).
#pragma once

#include "fiber/Fiber.hpp"

#include <array>

namespace dropletFiber
{

struct BinderSums
{
    // length, bare length, captured mass, sum l sigma^2 (= m^2 / l), hits, segments, and
    // for the expected mode's mass: bare length, mass, sum l sigma^2
    std::array<double, 9> values{};

    void add(const Fiber& fiber);
    BinderSums& operator+=(const BinderSums& other);
};

struct BinderFigures
{
    double length = 0.0;
    double bareFraction = 0.0;
    double meanSigma = 0.0;
    double sigmaVariation = 0.0; // coefficient of variation (0 where the mean is 0)
    double hitsPerLength = 0.0;
    // The expected mode's, on the same fibers
    double expectedBareFraction = 0.0;
    double expectedMeanSigma = 0.0;
    double expectedSigmaVariation = 0.0;
};

BinderFigures binderFigures(const BinderSums& sums);

} // namespace dropletFiber
