#include "grid/SeparableWeight.hpp"

#include "grid/GaussLegendre.hpp"
#include "grid/SeparableLanes.hpp"

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

// The parts of the bound that depend on Q alone, per Q (computed once: chooseQuadrature
// runs per wide parcel, in the deposit and again in the removal).
struct BoundTerms
{
    std::array<double, SeparableWeight::maximumPoints + 1> logFactorialQ{};
    std::array<double, SeparableWeight::maximumPoints + 1> logFactorial2Q{};
    std::array<double, SeparableWeight::maximumPoints + 1> log2QPlus1{};
    double log4 = 0.0;
};

const BoundTerms& boundTerms()
{
    static const BoundTerms terms = []
    {
        BoundTerms t;
        for (int n = 1; n <= SeparableWeight::maximumPoints; ++n)
        {
            const double q = n;
            t.logFactorialQ[static_cast<std::size_t>(n)] = std::lgamma(q + 1.0);
            t.logFactorial2Q[static_cast<std::size_t>(n)] = std::lgamma(2.0 * q + 1.0);
            t.log2QPlus1[static_cast<std::size_t>(n)] = std::log(2.0 * q + 1.0);
        }
        t.log4 = std::log(4.0);
        return t;
    }();
    return terms;
}

} // namespace

static_assert(SeparableWeight::maximumPoints == SeparableLanes::maximumPoints,
              "SeparableLanes::addRows holds a row's factors for every Q SeparableWeight takes");

SeparableWeight::SeparableWeight(bool vectorised) : lanes_(vectorised && SeparableLanes::available()) {}

double SeparableWeight::quadratureBound(int points, double k)
{
    // In logarithms: (2Q)! reaches 1e25 at Q = 12.
    const double q = points;
    if (!(k > 0.0))
    {
        return 0.0;
    }
    // The same values from the table for the Q chooseQuadrature tries, computed otherwise
    const BoundTerms& terms = boundTerms();
    const bool tabled = points >= 1 && points <= maximumPoints;
    const auto u = static_cast<std::size_t>(tabled ? points : 0);
    const double logFactorialQ = tabled ? terms.logFactorialQ[u] : std::lgamma(q + 1.0);
    const double logFactorial2Q = tabled ? terms.logFactorial2Q[u] : std::lgamma(2.0 * q + 1.0);
    const double log2QPlus1 = tabled ? terms.log2QPlus1[u] : std::log(2.0 * q + 1.0);
    const double logBound = 2.0 * q * std::log(k) + 0.5 * (q * terms.log4 + logFactorial2Q)
        + 4.0 * logFactorialQ - log2QPlus1 - 3.0 * logFactorial2Q;
    return cramerConstant * std::exp(logBound);
}

int SeparableWeight::chooseQuadrature(double k, double edgeValue, double threshold, double largestWeightBound,
                                      std::size_t boxNodes)
{
    if (!(largestWeightBound > 0.0) || !std::isfinite(k))
    {
        return 0;
    }
    const double nodes = 2.0 * static_cast<double>(boxNodes) + 1.0;
    const double budget = tolerance - 2.0 * relativeRounding;
    for (int points = 1; points <= maximumPoints; ++points)
    {
        const double perNode = quadratureBound(points, k) + edgeValue * (1.0 + relativeRounding)
            + argumentRounding + threshold;
        if (nodes * perNode / largestWeightBound <= budget)
        {
            return points;
        }
    }
    return 0;
}

void SeparableWeight::prepare(const PathWeight& path, const Eigen::Vector3d& start,
                              const Eigen::Vector3d& displacement, int points,
                              const std::array<const double*, 3>& coordinates, const std::array<int, 3>& lo,
                              const std::array<int, 3>& hi)
{
    if (points < 1 || points > maximumPoints)
    {
        throw std::invalid_argument("SeparableWeight: points must lie in [1, maximumPoints]");
    }
    const UnitRules& rules = unitRules();
    points_ = path.stationary() ? 1 : points; // a point: its midpoint, as PathWeight takes it
    for (int q = 0; q < points_; ++q)
    {
        const auto u = static_cast<std::size_t>(q);
        tau_[u] = path.stationary() ? 0.5 : rules.tau[static_cast<std::size_t>(points_)][u];
        weight_[u] = path.stationary() ? 1.0 : rules.weight[static_cast<std::size_t>(points_)][u];
    }
    for (int d = 0; d < 3; ++d)
    {
        axisTable(d, coordinates[static_cast<std::size_t>(d)], lo[static_cast<std::size_t>(d)],
                  hi[static_cast<std::size_t>(d)], path.kernel().gamma(), start, displacement);
    }
    rowsPrepared_ = false; // built by the first row(): fold() may change the tables first
}

void SeparableWeight::axisTable(int d, const double* coordinate, int lo, int hi, double gamma,
                                const Eigen::Vector3d& start, const Eigen::Vector3d& displacement)
{
    const auto n = static_cast<std::size_t>(hi - lo + 1);
    std::vector<double>& factor = factor_[static_cast<std::size_t>(d)];
    length_[static_cast<std::size_t>(d)] = n;
    factor.resize(n * static_cast<std::size_t>(points_));
    for (int q = 0; q < points_; ++q)
    {
        const double centre = start[d] + tau_[static_cast<std::size_t>(q)] * displacement[d];
        double* f = factor.data() + static_cast<std::size_t>(q) * n;
        if (lanes_)
        {
            SeparableLanes::gaussianTable(coordinate + lo, n, centre, gamma, f);
            continue;
        }
        for (std::size_t i = 0; i < n; ++i)
        {
            const double s = coordinate[lo + static_cast<int>(i)] - centre;
            f[i] = std::exp(-gamma * s * s);
        }
    }
}

void SeparableWeight::fold(const std::array<std::vector<int>, 3>& image, const std::array<int, 3>& foldedLo,
                           const std::array<int, 3>& foldedHi)
{
    for (std::size_t d = 0; d < 3; ++d)
    {
        // Each lattice index's factor added to its node's (per point q), in lattice order.
        const std::size_t n = length_[d];
        const auto m = static_cast<std::size_t>(foldedHi[d] - foldedLo[d] + 1);
        if (m == n && image[d].front() == foldedLo[d] && image[d].back() == foldedHi[d])
        {
            continue; // no ghost node in this direction: the images are the nodes themselves
        }
        folded_[d].assign(m * static_cast<std::size_t>(points_), 0.0);
        for (int q = 0; q < points_; ++q)
        {
            const double* from = factor_[d].data() + static_cast<std::size_t>(q) * n;
            double* to = folded_[d].data() + static_cast<std::size_t>(q) * m;
            for (std::size_t i = 0; i < n; ++i)
            {
                to[image[d][i] - foldedLo[d]] += from[i];
            }
        }
        factor_[d].swap(folded_[d]);
        length_[d] = m;
    }
    rowsPrepared_ = false; // built by the first row(): fold() may change the tables first
}

const double* SeparableWeight::row(int j, int k)
{
    return row(j, k, 0, length_[0]);
}

void SeparableWeight::setRowFactors(int j, int k, std::size_t first, std::size_t count)
{
    if (first + count > length_[0] || static_cast<std::size_t>(j) >= length_[1]
        || static_cast<std::size_t>(k) >= length_[2])
    {
        throw std::out_of_range("SeparableWeight::row: a row or positions beyond the box");
    }
    if (!rowsPrepared_)
    {
        prepareRows();
    }
    // (W_q Y_q(j)) Z_q(k): the first product kept per j (prepareRows)
    const auto points = static_cast<std::size_t>(points_);
    const double* weightedY = pointMajor_[0].data() + static_cast<std::size_t>(j) * points;
    const double* z = pointMajor_[1].data() + static_cast<std::size_t>(k) * points;
    for (std::size_t q = 0; q < points; ++q)
    {
        rowFactor_[q] = weightedY[q] * z[q];
    }
}

const double* SeparableWeight::row(int j, int k, std::size_t first, std::size_t count)
{
    setRowFactors(j, k, first, count);
    const std::size_t n = length_[0];
    // sum_q W_q X_q(i) Y_q(j) Z_q(k): one multiply-add per node and point.
    double* omega = rowOmega_.data();
    if (lanes_)
    {
        SeparableLanes::row(rowFactor_.data(), points_, factor_[0].data() + first, n, count, omega);
        return omega;
    }
    const double r0 = rowFactor_[0];
    const double* f0 = factor_[0].data() + first;
    for (std::size_t i = 0; i < count; ++i)
    {
        omega[i] = r0 * f0[i];
    }
    for (int q = 1; q < points_; ++q)
    {
        const double r = rowFactor_[static_cast<std::size_t>(q)];
        const double* f = factor_[0].data() + static_cast<std::size_t>(q) * n + first;
        for (std::size_t i = 0; i < count; ++i)
        {
            omega[i] += r * f[i];
        }
    }
    return omega;
}

void SeparableWeight::addRowsInLanes(const std::array<int, 3>& lo, const std::array<int, 3>& hi,
                                     double inverseSum, const double* totals, SeparableLanes::BoxRows to)
{
    if (lo[0] > hi[0] || lo[1] > hi[1] || lo[2] > hi[2])
    {
        return;
    }
    if (lo[0] < 0 || lo[1] < 0 || lo[2] < 0 || static_cast<std::size_t>(hi[0]) >= length_[0]
        || static_cast<std::size_t>(hi[1]) >= length_[1] || static_cast<std::size_t>(hi[2]) >= length_[2])
    {
        throw std::out_of_range("SeparableWeight::addRowsInLanes: rows or positions beyond the box");
    }
    if (!lanes_)
    {
        throw std::logic_error("SeparableWeight::addRowsInLanes: the tables are not in lanes");
    }
    if (!rowsPrepared_)
    {
        prepareRows();
    }
    const auto points = static_cast<std::size_t>(points_);
    to.weightedY = pointMajor_[0].data() + static_cast<std::size_t>(lo[1]) * points;
    to.z = pointMajor_[1].data() + static_cast<std::size_t>(lo[2]) * points;
    to.rows = static_cast<std::size_t>(hi[1] - lo[1] + 1);
    to.layers = static_cast<std::size_t>(hi[2] - lo[2] + 1);
    to.points = points_;
    to.factor = factor_[0].data() + lo[0];
    to.stride = length_[0];
    to.count = static_cast<std::size_t>(hi[0] - lo[0] + 1);
    SeparableLanes::addRows(to, inverseSum, totals);
}

double SeparableTables::omega(int i, int j, int k) const
{
    const std::size_t n = length[0], ny = length[1], nz = length[2];
    const auto x = static_cast<std::size_t>(i);
    const auto y = static_cast<std::size_t>(j);
    const auto z = static_cast<std::size_t>(k);
    // row(): the row factor (W_q Y_q(j)) Z_q(k), then omega = r_0 X_0(i) + r_1 X_1(i) + ...,
    // each term fused (one rounding) where row() runs in lanes, as SeparableLanes::row does.
    const double* fx = factor[0];
    const double* fy = factor[1];
    const double* fz = factor[2];
    double value = weight[0] * fy[y] * fz[z] * fx[x];
    for (int q = 1; q < points; ++q)
    {
        const auto u = static_cast<std::size_t>(q);
        const double r = weight[u] * fy[u * ny + y] * fz[u * nz + z];
        value = lanes ? std::fma(r, fx[u * n + x], value) : value + r * fx[u * n + x];
    }
    return value;
}

SeparableTables SeparableWeight::tables() const
{
    SeparableTables view;
    view.points = points_;
    view.lanes = lanes_;
    view.length = length_;
    view.weight = weight_.data();
    for (std::size_t d = 0; d < 3; ++d)
    {
        view.factor[d] = factor_[d].data();
    }
    return view;
}

std::size_t SeparableWeight::tableValues() const
{
    return static_cast<std::size_t>(points_) * (1 + length_[0] + length_[1] + length_[2]);
}

void SeparableWeight::copyTables(double* to) const
{
    const auto points = static_cast<std::size_t>(points_);
    to = std::copy(weight_.begin(), weight_.begin() + static_cast<std::ptrdiff_t>(points), to);
    for (std::size_t d = 0; d < 3; ++d)
    {
        const double* from = factor_[d].data();
        to = std::copy(from, from + points * length_[d], to);
    }
}

SeparableTables SeparableTables::inCompactCopy(const double* values, int points, bool lanes,
                                               const std::array<std::size_t, 3>& length)
{
    // copyTables' layout: W_q, then the x, y and z factors, q-major
    SeparableTables tables;
    tables.points = points;
    tables.lanes = lanes;
    tables.length = length;
    tables.weight = values;
    values += points;
    for (std::size_t d = 0; d < 3; ++d)
    {
        tables.factor[d] = values;
        values += static_cast<std::size_t>(points) * length[d];
    }
    return tables;
}

void SeparableWeight::prepareRows()
{
    rowsPrepared_ = true;
    rowOmega_.resize(length_[0]);
    const auto points = static_cast<std::size_t>(points_);
    for (std::size_t d = 1; d < 3; ++d)
    {
        // y weighted: W_q Y_q(j), the row factor's first product (row())
        std::vector<double>& to = pointMajor_[d - 1];
        to.resize(length_[d] * points);
        for (std::size_t q = 0; q < points; ++q)
        {
            const double* from = factor_[d].data() + q * length_[d];
            for (std::size_t i = 0; i < length_[d]; ++i)
            {
                to[i * points + q] = d == 1 ? weight_[q] * from[i] : from[i];
            }
        }
    }
}

double SeparableWeight::sum() const
{
    if (lanes_)
    {
        return sumInLanes();
    }
    double total = 0.0;
    for (int q = 0; q < points_; ++q)
    {
        const auto u = static_cast<std::size_t>(q);
        double product = weight_[u];
        for (std::size_t d = 0; d < 3; ++d)
        {
            // Neumaier's compensated sum of the axis's factors for point q (positive terms)
            const double* f = factor_[d].data() + u * length_[d];
            double axisSum = 0.0, compensation = 0.0;
            for (std::size_t i = 0; i < length_[d]; ++i)
            {
                const double next = axisSum + f[i];
                compensation += axisSum >= f[i] ? (axisSum - next) + f[i] : (f[i] - next) + axisSum;
                axisSum = next;
            }
            product *= axisSum + compensation;
        }
        total += product;
    }
    return total;
}

double SeparableWeight::sumInLanes() const
{
    // The 3 Q per-axis sums four at a time (SeparableLanes::compensatedSums: sum()'s
    // operations per table), then sum()'s products in sum()'s order
    const auto points = static_cast<std::size_t>(points_);
    std::array<const double*, 3 * maximumPoints> tables{};
    std::array<std::size_t, 3 * maximumPoints> lengths{};
    std::array<double, 3 * maximumPoints> axisSums{};
    for (std::size_t q = 0; q < points; ++q)
    {
        for (std::size_t d = 0; d < 3; ++d)
        {
            tables[3 * q + d] = factor_[d].data() + q * length_[d];
            lengths[3 * q + d] = length_[d];
        }
    }
    for (std::size_t t = 0; t < 3 * points; t += 4)
    {
        SeparableLanes::compensatedSums(tables.data() + t, lengths.data() + t,
                                        std::min<std::size_t>(4, 3 * points - t), axisSums.data() + t);
    }
    double total = 0.0;
    for (std::size_t q = 0; q < points; ++q)
    {
        double product = weight_[q];
        for (std::size_t d = 0; d < 3; ++d)
        {
            product *= axisSums[3 * q + d];
        }
        total += product;
    }
    return total;
}

} // namespace dropletFiber
