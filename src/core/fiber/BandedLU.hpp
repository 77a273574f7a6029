// BandedLU: LU factorisation with partial (row) pivoting of a square band matrix,
// the algorithm of LAPACK's dgbtf2/dgbtrs written out for Eigen vectors.
// Why not an Eigen solver: Eigen has band storage (BandMatrix) but no band
// factorisation, and SparseLU on these small, narrow systems (bandwidth 10, a few
// hundred unknowns per fiber) spends more on its symbolic bookkeeping than on the
// arithmetic. This costs O(n kl (kl+ku)) per factorisation - linear in the number
// of fiber points - allocates nothing once sized, and is deterministic.
// Pivoting is needed: the fiber systems are saddle-point (KKT) systems with zero
// diagonal entries in the constraint rows. Threshold partial pivoting (as in sparse
// LU codes, e.g. UMFPACK's default 0.1): the diagonal entry is kept as pivot when it
// is at least pivotThreshold times the largest entry of its column below, so every
// multiplier is at most 1 / pivotThreshold; 1 is classic partial pivoting (LAPACK).
// A row exchange widens U by up to kl columns, so on nearly diagonally dominant
// matrices a threshold below 1 saves work. Like dgbtf2, the elimination only runs
// over the columns that row exchanges have actually filled (ju), not over the whole
// room kept for fill: with few exchanges that halves the work, and the skipped
// entries are exact zeros, so the factors are the same bits either way.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace dropletFiber
{

class BandedLU
{
public:
    // n x n matrix with kl sub- and ku super-diagonals; all entries zero.
    void reset(Eigen::Index n, Eigen::Index kl, Eigen::Index ku);
    // Becomes a copy of other's matrix (not its factors); no allocation once sized.
    // Cheaper than reset() + adding a matrix's constant part again every time.
    void assignMatrix(const BandedLU& other);

    // In (0, 1]; default 1 (partial pivoting). Kept by reset().
    void setPivotThreshold(double threshold);
    double pivotThreshold() const { return pivotThreshold_; }

    Eigen::Index size() const { return n_; }
    // A(i, j) += value; requires -kl <= j - i <= ku.
    void add(Eigen::Index i, Eigen::Index j, double value)
    {
        band_[static_cast<std::size_t>(i * width_ + (j - i + kl_))] += value;
    }
    double coeff(Eigen::Index i, Eigen::Index j) const;

    // Factorise in place; false if a pivot is exactly zero (singular matrix).
    bool factorize();
    // Solve A x = b with the factors (b is overwritten by x).
    void solveInPlace(Eigen::VectorXd& b) const;
    // Row exchanges made by the last factorize() (diagnostics, tests).
    Eigen::Index rowExchanges() const { return rowExchanges_; }

private:
    // Row i's storage, indexed by column: rowPointer(i)[j] = A(i, j) for
    // i - kl <= j <= i + kl + ku (band_[i * width + j - i + kl]).
    double* rowPointer(Eigen::Index i) { return band_.data() + i * (width_ - 1) + kl_; }
    const double* rowPointer(Eigen::Index i) const { return band_.data() + i * (width_ - 1) + kl_; }

    Eigen::Index n_ = 0, kl_ = 0, ku_ = 0;
    Eigen::Index width_ = 0; // kl + (kl + ku) + 1: room for pivoting fill
    double pivotThreshold_ = 1.0;
    Eigen::Index rowExchanges_ = 0;
    std::vector<double> band_;             // row i: columns i-kl .. i+kl+ku
    std::vector<double> lower_;            // multipliers, kl per column
    std::vector<Eigen::Index> pivot_;      // row swapped with k at step k
    std::vector<Eigen::Index> lastColumn_; // last nonzero column of U's row k
    std::vector<double> inverseDiagonal_;  // 1 / U(k, k)
};

} // namespace dropletFiber
