// BandedLU against Eigen's dense LU on banded matrices, including ones with zero
// diagonal entries that need pivoting (like the fiber saddle-point systems).
#include "fiber/BandedLU.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <random>

using dropletFiber::BandedLU;

TEST(BandedLU, MatchesDenseSolveWithPivoting)
{
    std::mt19937 generator(7);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    for (int n : {1, 5, 37, 120}) {
        const int kl = 4, ku = 3;
        BandedLU lu;
        lu.reset(n, kl, ku);
        Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
        for (int i = 0; i < n; ++i) {
            for (int j = std::max(0, i - kl); j <= std::min(n - 1, i + ku); ++j) {
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

TEST(BandedLU, ReportsSingularMatrix)
{
    BandedLU lu;
    lu.reset(3, 1, 1);
    lu.add(0, 0, 1.0);
    lu.add(1, 1, 0.0);
    lu.add(2, 2, 1.0);
    EXPECT_FALSE(lu.factorize());
}
