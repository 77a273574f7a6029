#include "grid/GaussLegendre.hpp"

#include <cmath>

namespace dropletFiber
{

namespace
{

GaussLegendreRule makeRule()
{
    GaussLegendreRule rule;
    gaussLegendreRule(GaussLegendreRule::order, rule.node.data(), rule.weight.data());
    return rule;
}

} // namespace

void gaussLegendreRule(int n, double* node, double* weight)
{
    constexpr double pi = 3.14159265358979323846;
    for (int i = 0; i < n; ++i)
    {
        // Standard initial guess for the i-th root, then Newton on P_n.
        double x = std::cos(pi * (i + 0.75) / (n + 0.5));
        double derivative = 1.0;
        for (int iteration = 0; iteration < 100; ++iteration)
        {
            double p0 = 1.0;
            double p1 = x;
            for (int k = 2; k <= n; ++k)
            {
                const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            derivative = n * (x * p1 - p0) / (x * x - 1.0);
            const double step = p1 / derivative;
            x -= step;
            if (std::abs(step) < 1e-17)
            {
                break;
            }
        }
        node[i] = x;
        weight[i] = 2.0 / ((1.0 - x * x) * derivative * derivative);
    }
}

const GaussLegendreRule& gaussLegendre()
{
    static const GaussLegendreRule rule = makeRule();
    return rule;
}

} // namespace dropletFiber
