// BandedLU: LU factorisation with partial (row) pivoting of a square band matrix,
// the algorithm of LAPACK's dgbtf2/dgbtrs written out for Eigen vectors.
// Why not an Eigen solver: Eigen has band storage (BandMatrix) but no band
// factorisation, and SparseLU on these small, narrow systems (bandwidth 10, a few
// hundred unknowns per fiber) spends more on its symbolic bookkeeping than on the
// arithmetic. This costs O(n kl (kl+ku)) per factorisation - linear in the number
// of fiber points - allocates nothing once sized, and is deterministic.
// Pivoting is needed: the fiber systems are saddle-point (KKT) systems with zero
// diagonal entries in the constraint rows.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace dropletFiber {

class BandedLU {
public:
    // n x n matrix with kl sub- and ku super-diagonals; all entries zero.
    void reset(Eigen::Index n, Eigen::Index kl, Eigen::Index ku);

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

private:
    double& at(Eigen::Index i, Eigen::Index j)
    {
        return band_[static_cast<std::size_t>(i * width_ + (j - i + kl_))];
    }
    double at(Eigen::Index i, Eigen::Index j) const
    {
        return band_[static_cast<std::size_t>(i * width_ + (j - i + kl_))];
    }

    Eigen::Index n_ = 0, kl_ = 0, ku_ = 0;
    Eigen::Index width_ = 0;              // kl + (kl + ku) + 1: room for pivoting fill
    std::vector<double> band_;            // row i: columns i-kl .. i+kl+ku
    std::vector<double> lower_;           // multipliers, kl per column
    std::vector<Eigen::Index> pivot_;     // row swapped with k at step k
};

}  // namespace dropletFiber
