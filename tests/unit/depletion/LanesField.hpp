// Test helper (not a test file): the penetration the grid model leaves behind a mat of fibers
// across a straight spray (StraightSpray.hpp: lanes at x = (j/4 + 1/8) h, nodes on the
// bounds) in the limit of small steps, from the fibers' positions alone (docs/model.md sec. 7,
// thick fibers, P20 and P21). A fiber at x_F with strip c asks each node column n for the
// fraction phi_n = (c / h) hat_n(x_F) / H_n of its droplets over its crossing (H_n the
// column's dual width in spacings: 1/2 on a face); a lane at x collects
// sum_n hat_n(x) phi'_n and keeps exp(-that).
//   unshadowed: phi'_n = phi_n (the depths linear, no self-shadow: P20's lanes)
//   shadowed:   phi'_n = phi_n (1 + <f>_n / 2), <f>_n the mean over hat_n of the fiber's own
//               lane depth f = sum_m phi_m hat_m, here integrated numerically (P21)
// The mean over the lanes of exp(-depth) is the model's penetration for that mat: it holds
// the mat's own clustering at the grid's scale, which exp(-S) does not.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace dropletFiber
{
namespace test
{

struct LanesField
{
    double unshadowed = 0.0, shadowed = 0.0;
};

inline double hatFunction(double u)
{
    return std::max(0.0, 1.0 - std::abs(u));
}

// xs: the fibers' positions across the flow (m); strip: 2 (r_F + r_p); columns: spacings.
inline LanesField lanesField(const std::vector<double>& xs, double strip, double h, int columns)
{
    const auto nodes = static_cast<std::size_t>(columns) + 1;
    const auto dual = [columns](int n) { return n == 0 || n == columns ? 0.5 : 1.0; };
    std::vector<double> plain(nodes, 0.0), shadowed(nodes, 0.0);
    for (const double x : xs)
    {
        const double u = x / h; // in spacings
        const int lower = std::min(static_cast<int>(std::floor(u)), columns - 1);
        std::vector<double> phi(nodes, 0.0);
        for (int n = lower; n <= lower + 1; ++n)
        {
            phi[static_cast<std::size_t>(n)] = strip / h * hatFunction(u - n) / dual(n);
        }
        for (int n = lower; n <= lower + 1; ++n)
        {
            // <f>_n: the midpoint rule on 400 pieces of node n's hat within the box (f and
            // hat_n are linear on each piece between nodes: the error is O(1e-6) of it)
            const int pieces = 400;
            const double from = std::max(0, n - 1), to = std::min(columns, n + 1);
            double weighted = 0.0, weights = 0.0;
            for (int k = 0; k < pieces; ++k)
            {
                const double y = from + (to - from) * (k + 0.5) / pieces;
                double f = 0.0;
                for (int m = lower; m <= lower + 1; ++m)
                {
                    f += phi[static_cast<std::size_t>(m)] * hatFunction(y - m);
                }
                weighted += hatFunction(y - n) * f;
                weights += hatFunction(y - n);
            }
            const auto i = static_cast<std::size_t>(n);
            plain[i] += phi[i];
            shadowed[i] += phi[i] * (1.0 + 0.5 * weighted / weights);
        }
    }
    LanesField field;
    const int lanes = 4 * columns;
    for (int j = 0; j < lanes; ++j)
    {
        const double y = 0.25 * j + 0.125; // in spacings
        double depth = 0.0, shadowedDepth = 0.0;
        for (int n = 0; n <= columns; ++n)
        {
            depth += plain[static_cast<std::size_t>(n)] * hatFunction(y - n);
            shadowedDepth += shadowed[static_cast<std::size_t>(n)] * hatFunction(y - n);
        }
        field.unshadowed += std::exp(-depth) / lanes;
        field.shadowed += std::exp(-shadowedDepth) / lanes;
    }
    return field;
}

} // namespace test
} // namespace dropletFiber
