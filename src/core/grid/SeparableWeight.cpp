#include "grid/SeparableWeight.hpp"

#include "grid/GaussLegendre.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dropletFiber
{

namespace
{

// Cramer's bound: |H_m(x)| exp(-x^2 / 2) <= 1.086435 sqrt(2^m m!).
constexpr double cramerConstant = 1.086435;

// Gauss-Legendre points and weights on [0, 1] for 1..maximumPoints points, computed once.
struct UnitRules
{
    std::array<std::array<double, SeparableWeight::maximumPoints>, SeparableWeight::maximumPoints + 1> tau{};
    std::array<std::array<double, SeparableWeight::maximumPoints>, SeparableWeight::maximumPoints + 1>
        weight{};
};

const UnitRules& unitRules()
{
    static const UnitRules rules = []
    {
        UnitRules r;
        for (int n = 1; n <= SeparableWeight::maximumPoints; ++n)
        {
            std::array<double, SeparableWeight::maximumPoints> node{}, weight{};
            gaussLegendreRule(n, node.data(), weight.data());
            for (int q = 0; q < n; ++q)
            {
                r.tau[n][q] = 0.5 * (1.0 + node[q]);
                r.weight[n][q] = 0.5 * weight[q];
            }
        }
        return r;
    }();
    return rules;
}

} // namespace

double SeparableWeight::quadratureBound(int points, double k)
{
    // In logarithms: (2Q)! reaches 1e25 at Q = 12.
    const double q = points;
    const double logFactorialQ = std::lgamma(q + 1.0);
    const double logFactorial2Q = std::lgamma(2.0 * q + 1.0);
    if (!(k > 0.0))
    {
        return 0.0;
    }
    const double logBound = 2.0 * q * std::log(k) + 0.5 * (q * std::log(4.0) + logFactorial2Q)
        + 4.0 * logFactorialQ - std::log(2.0 * q + 1.0) - 3.0 * logFactorial2Q;
    return cramerConstant * std::exp(logBound);
}

int SeparableWeight::chooseQuadrature(double k, double edgeValue, double largestWeightBound,
                                      std::size_t boxNodes)
{
    if (!(largestWeightBound > 0.0) || !std::isfinite(k))
    {
        return 0;
    }
    const double nodes = static_cast<double>(boxNodes) + 1.0;
    const double budget = tolerance - 2.0 * relativeRounding;
    for (int points = 1; points <= maximumPoints; ++points)
    {
        const double perNode = quadratureBound(points, k) + edgeValue * (1.0 + relativeRounding);
        if (nodes * perNode / largestWeightBound <= budget)
        {
            return points;
        }
    }
    return 0;
}

const double* SeparableWeight::boxOmegas(const PathWeight& path, const Eigen::Vector3d& start,
                                         const Eigen::Vector3d& displacement, int points, const double* x,
                                         const double* y, const double* z, const std::array<int, 3>& lo,
                                         const std::array<int, 3>& hi)
{
    if (points < 1 || points > maximumPoints)
    {
        throw std::invalid_argument("SeparableWeight: points must lie in [1, maximumPoints]");
    }
    const UnitRules& rules = unitRules();
    for (int q = 0; q < points; ++q)
    {
        tau_[q] = path.stationary() ? 0.5 : rules.tau[points][q];
        weight_[q] = path.stationary() ? 1.0 : rules.weight[points][q];
    }
    direction_ = path.stationary() ? Eigen::Vector3d::Zero() : Eigen::Vector3d(displacement / path.length());
    const std::array<const double*, 3> coordinates{{x, y, z}};
    for (int d = 0; d < 3; ++d)
    {
        axisTables(d, coordinates[d], lo[d], hi[d], path, start, displacement, points);
    }
    const std::size_t rowLength = offset_[0].size();
    const std::size_t rows = offset_[1].size() * offset_[2].size();
    omega_.resize(rowLength * rows);
    rowSum_.resize(rowLength);
    double* omega = omega_.data();
    for (std::size_t k = 0; k < offset_[2].size(); ++k)
    {
        for (std::size_t j = 0; j < offset_[1].size(); ++j, omega += rowLength)
        {
            rowOmegas(static_cast<int>(j), static_cast<int>(k), points, path, omega);
        }
    }
    return omega_.data();
}

void SeparableWeight::axisTables(int d, const double* coordinate, int lo, int hi, const PathWeight& path,
                                 const Eigen::Vector3d& start, const Eigen::Vector3d& displacement,
                                 int points)
{
    const auto n = static_cast<std::size_t>(hi - lo + 1);
    std::vector<double>& offset = offset_[static_cast<std::size_t>(d)];
    std::vector<double>& factor = factor_[static_cast<std::size_t>(d)];
    offset.resize(n);
    factor.resize(n * static_cast<std::size_t>(points));
    const double gamma = path.kernel().gamma();
    // The node test uses PathWeight's distances: from the start along the path line, or
    // (stationary) from the midpoint, offset - displacement / 2 rounded as it rounds them.
    const double shift = path.stationary() ? 0.5 * displacement[d] : 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
        offset[i] = (coordinate[lo + static_cast<int>(i)] - start[d]) - shift;
    }
    for (int q = 0; q < points; ++q)
    {
        const double centre = start[d] + tau_[q] * displacement[d];
        double* f = factor.data() + static_cast<std::size_t>(q) * n;
        for (std::size_t i = 0; i < n; ++i)
        {
            const double s = coordinate[lo + static_cast<int>(i)] - centre;
            f[i] = std::exp(-gamma * s * s);
        }
    }
}

void SeparableWeight::rowOmegas(int j, int k, int points, const PathWeight& path, double* omega)
{
    const std::size_t n = offset_[0].size();
    const double* px = offset_[0].data();
    const double py = offset_[1][static_cast<std::size_t>(j)];
    const double pz = offset_[2][static_cast<std::size_t>(k)];
    const double ux = direction_.x(), uy = direction_.y(), uz = direction_.z();
    const double cutoffSquared = path.cutoffSquared();
    const double edgeValue = path.kernel().edgeValue();
    const std::size_t ny = offset_[1].size(), nz = offset_[2].size();
    for (int q = 0; q < points; ++q)
    {
        const auto u = static_cast<std::size_t>(q);
        rowFactor_[u] = weight_[u] * factor_[1][u * ny + static_cast<std::size_t>(j)]
            * factor_[2][u * nz + static_cast<std::size_t>(k)];
    }
    // sum_q W_q f_x,q(i) f_y,q(j) f_z,q(k): one multiply-add per node and point.
    std::fill(rowSum_.begin(), rowSum_.end(), 0.0);
    for (int q = 0; q < points; ++q)
    {
        const double r = rowFactor_[static_cast<std::size_t>(q)];
        const double* f = factor_[0].data() + static_cast<std::size_t>(q) * n;
        for (std::size_t i = 0; i < n; ++i)
        {
            rowSum_[i] += r * f[i];
        }
    }
    // Keep the nodes PathWeight keeps: squared distance from the path line below the cut-off.
    const double lambdaYZ = uy * py + uz * pz;
    for (std::size_t i = 0; i < n; ++i)
    {
        const double lambda = ux * px[i] + lambdaYZ;
        const double rx = px[i] - lambda * ux, ry = py - lambda * uy, rz = pz - lambda * uz;
        const double distanceSquared = rx * rx + ry * ry + rz * rz;
        const double value = std::max(rowSum_[i] - edgeValue, 0.0);
        omega[i] = distanceSquared < cutoffSquared ? value : 0.0;
    }
}

} // namespace dropletFiber
