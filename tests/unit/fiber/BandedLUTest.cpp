// BandedLU against Eigen's dense LU on banded matrices, including ones with zero
// diagonal entries that need pivoting (like the fiber saddle-point systems).
#include "fiber/BandedLU.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

using dropletFiber::BandedLU;

TEST(BandedLU, MatchesDenseSolveWithPivoting)
{
    std::mt19937 generator(7);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    for (int n : {1, 5, 37, 120})
    {
        const int kl = 4, ku = 3;
        BandedLU lu;
        lu.reset(n, kl, ku);
        Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
        for (int i = 0; i < n; ++i)
        {
            for (int j = std::max(0, i - kl); j <= std::min(n - 1, i + ku); ++j)
            {
                // every 4th diagonal entry is zero: forces row exchanges
                const double value = (i == j && i % 4 == 3) ? 0.0 : uniform(generator);
                lu.add(i, j, value);
                dense(i, j) = value;
            }
        }
        Eigen::VectorXd b = Eigen::VectorXd::NullaryExpr(n, [&]() { return uniform(generator); });
        const Eigen::VectorXd expected = dense.fullPivLu().solve(b);
        ASSERT_TRUE(lu.factorize());
        lu.solveInPlace(b);
        EXPECT_LT((b - expected).norm(), 1e-9 * (1.0 + expected.norm())) << "n = " << n;
    }
}

TEST(BandedLU, MatchesDenseSolveWithThresholdPivoting)
{
    std::mt19937 generator(11);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    const int n = 60, kl = 5, ku = 4;
    for (double threshold : {0.5, 0.1, 0.01})
    {
        BandedLU lu;
        lu.setPivotThreshold(threshold);
        lu.reset(n, kl, ku);
        Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
        for (int i = 0; i < n; ++i)
        {
            for (int j = std::max(0, i - kl); j <= std::min(n - 1, i + ku); ++j)
            {
                // diagonal often smaller than its column: some exchanges, some not
                const double value = (i == j && i % 3 == 0) ? 0.05 * uniform(generator) : uniform(generator);
                lu.add(i, j, value);
                dense(i, j) = value;
            }
        }
        Eigen::VectorXd b = Eigen::VectorXd::NullaryExpr(n, [&]() { return uniform(generator); });
        const Eigen::VectorXd expected = dense.fullPivLu().solve(b);
        ASSERT_TRUE(lu.factorize());
        EXPECT_GT(lu.rowExchanges(), 0);
        EXPECT_LT(lu.rowExchanges(), n);
        lu.solveInPlace(b);
        EXPECT_LT((b - expected).norm(), 1e-9 * (1.0 + expected.norm())) << "threshold " << threshold;
    }
}

TEST(BandedLU, ReportsSingularMatrix)
{
    BandedLU lu;
    lu.reset(3, 1, 1);
    lu.add(0, 0, 1.0);
    lu.add(1, 1, 0.0);
    lu.add(2, 2, 1.0);
    EXPECT_FALSE(lu.factorize());
}

namespace
{

// The bending stencil (1, -4, 6, -4, 1) plus the identity: symmetric positive definite,
// and its LU without exchanges has multipliers of about 2 (the stencil is the square of
// (1, -2, 1)), so partial pivoting exchanges rows although no exchange is needed.
void addBendingMatrix(BandedLU& lu, Eigen::MatrixXd& dense, int n)
{
    const double stencil[5] = {1.0, -4.0, 6.0, -4.0, 1.0};
    dense = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i)
    {
        for (int o = -2; o <= 2; ++o)
        {
            const int j = i + o;
            if (j < 0 || j >= n)
                continue;
            const double value = 100.0 * stencil[o + 2] + (o == 0 ? 1.0 : 0.0);
            lu.add(i, j, value);
            dense(i, j) = value;
        }
    }
}

} // namespace

TEST(BandedLU, ThresholdKeepsDiagonalPivotsOfBendingMatrix)
{
    const int n = 40;
    Eigen::VectorXd b(n);
    for (int i = 0; i < n; ++i)
        b(i) = std::sin(0.3 * i) + 0.1 * i;
    for (double threshold : {1.0, 0.1})
    {
        BandedLU lu;
        lu.setPivotThreshold(threshold);
        lu.reset(n, 2, 2);
        Eigen::MatrixXd dense;
        addBendingMatrix(lu, dense, n);
        ASSERT_TRUE(lu.factorize());
        if (threshold == 1.0)
        {
            EXPECT_GT(lu.rowExchanges(), n / 2); // partial pivoting: about every row
        }
        else
        {
            EXPECT_EQ(lu.rowExchanges(), 0); // all multipliers are below 10 here
        }
        Eigen::VectorXd x = b;
        lu.solveInPlace(x);
        const Eigen::VectorXd expected = dense.ldlt().solve(b);
        EXPECT_LT((x - expected).norm(), 1e-12 * expected.norm()) << "threshold " << threshold;
    }
}

TEST(BandedLU, ThresholdStillExchangesForZeroAndSmallPivots)
{
    // [[0 1] [1 1]] needs an exchange at any threshold, and so does a diagonal
    // entry a thousand times smaller than the one below it at threshold 0.1.
    for (double small : {0.0, 1e-3})
    {
        BandedLU lu;
        lu.setPivotThreshold(0.1);
        lu.reset(2, 1, 1);
        lu.add(0, 0, small);
        lu.add(0, 1, 1.0);
        lu.add(1, 0, 1.0);
        lu.add(1, 1, 1.0);
        ASSERT_TRUE(lu.factorize());
        EXPECT_EQ(lu.rowExchanges(), 1);
        Eigen::VectorXd x(2);
        x << 1.0, 3.0; // expected values: Cramer's rule
        lu.solveInPlace(x);
        const double det = small - 1.0;
        EXPECT_NEAR(x(0), (1.0 * 1.0 - 1.0 * 3.0) / det, 1e-14);
        EXPECT_NEAR(x(1), (small * 3.0 - 1.0 * 1.0) / det, 1e-14);
    }
    BandedLU lu;
    EXPECT_THROW(lu.setPivotThreshold(0.0), std::invalid_argument);
    EXPECT_THROW(lu.setPivotThreshold(1.5), std::invalid_argument);
}

TEST(BandedLU, AssignMatrixCopiesTheMatrixNotTheFactors)
{
    // A prepared matrix copied into a solver that had factorised another one gives
    // the same solution as a fresh solver.
    const int n = 30;
    BandedLU prepared, fresh, reused;
    Eigen::MatrixXd dense;
    prepared.reset(n, 2, 2);
    addBendingMatrix(prepared, dense, n);
    fresh.reset(n, 2, 2);
    addBendingMatrix(fresh, dense, n);
    reused.reset(n, 2, 2);
    for (int i = 0; i < n; ++i)
        reused.add(i, i, 1.0 + i);
    ASSERT_TRUE(reused.factorize());
    reused.assignMatrix(prepared);
    EXPECT_EQ(reused.coeff(5, 3), dense(5, 3));
    ASSERT_TRUE(reused.factorize());
    ASSERT_TRUE(fresh.factorize());
    Eigen::VectorXd a = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0), b = a;
    reused.solveInPlace(a);
    fresh.solveInPlace(b);
    EXPECT_EQ(a, b); // same operations on the same numbers: same bits
    EXPECT_LT((dense * a - Eigen::VectorXd::LinSpaced(n, -1.0, 2.0)).norm(), 1e-10);
}
