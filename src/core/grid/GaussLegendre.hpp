// Gauss-Legendre rules on [-1, 1]. The 10-point rule is used by PathWeight only where the closed form of
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

// The n-point rule on [-1, 1] (n >= 1): node[0..n) and weight[0..n), by Newton iteration
// on the Legendre polynomial P_n (SeparableWeight uses n = 1 to 12).
void gaussLegendreRule(int n, double* node, double* weight);

// Computed once (Newton iteration on the Legendre polynomial), then shared.
const GaussLegendreRule& gaussLegendre();

} // namespace dropletFiber
