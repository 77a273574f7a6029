// Gauss-Legendre rule on [-1, 1], used by PathWeight only where the closed form of
// eq. 23 would lose digits to cancellation (short or edge-of-support intervals, where
// the integrand is smooth and nearly polynomial, so a fixed rule is exact to round-off).
#pragma once

#include <array>

namespace dropletFiber
{

struct GaussLegendreRule
{
    static constexpr int order = 10;
    std::array<double, order> node{};
    std::array<double, order> weight{};
};

// Computed once (Newton iteration on the Legendre polynomial), then shared.
const GaussLegendreRule& gaussLegendre();

} // namespace dropletFiber
