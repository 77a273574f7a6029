#include "fiber/BandedLU.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace dropletFiber {

void BandedLU::reset(Eigen::Index n, Eigen::Index kl, Eigen::Index ku)
{
    n_ = n;
    kl_ = kl;
    ku_ = ku;
    width_ = 2 * kl + ku + 1;
    band_.assign(static_cast<std::size_t>(n * width_), 0.0);
    lower_.assign(static_cast<std::size_t>(n * kl), 0.0);
    pivot_.assign(static_cast<std::size_t>(n), 0);
    lastColumn_.assign(static_cast<std::size_t>(n), 0);
}

void BandedLU::assignMatrix(const BandedLU& other)
{
    n_ = other.n_;
    kl_ = other.kl_;
    ku_ = other.ku_;
    width_ = other.width_;
    band_ = other.band_;  // same size: copies into the existing storage
    lower_.resize(static_cast<std::size_t>(n_ * kl_));
    pivot_.resize(static_cast<std::size_t>(n_));
    lastColumn_.resize(static_cast<std::size_t>(n_));
}

double BandedLU::coeff(Eigen::Index i, Eigen::Index j) const
{
    const Eigen::Index offset = j - i;
    if (offset < -kl_ || offset > kl_ + ku_) return 0.0;
    return rowPointer(i)[j];
}

bool BandedLU::factorize()
{
    // ju: last column any row of U so far reaches (dgbtf2's JU). Rows below k hold
    // nothing right of max(ju, their own i + ku), so columns past ju need no update.
    Eigen::Index ju = 0;
    for (Eigen::Index k = 0; k < n_; ++k) {
        const Eigen::Index lastRow = std::min(n_ - 1, k + kl_);
        Eigen::Index p = k;
        double biggest = std::abs(rowPointer(k)[k]);
        for (Eigen::Index i = k + 1; i <= lastRow; ++i) {
            const double candidate = std::abs(rowPointer(i)[k]);
            if (candidate > biggest) {
                biggest = candidate;
                p = i;
            }
        }
        pivot_[static_cast<std::size_t>(k)] = p;
        if (biggest == 0.0) return false;
        ju = std::max(ju, std::min(n_ - 1, p + ku_));
        lastColumn_[static_cast<std::size_t>(k)] = ju;
        double* pivotRow = rowPointer(k);
        if (p != k) {
            double* other = rowPointer(p);
            for (Eigen::Index j = k; j <= ju; ++j) std::swap(pivotRow[j], other[j]);
        }
        const double inversePivot = 1.0 / pivotRow[k];
        double* multipliers = lower_.data() + k * kl_;  // row i's at i - k - 1
        for (Eigen::Index i = k + 1; i <= lastRow; ++i) {
            double* row = rowPointer(i);
            const double factor = row[k] * inversePivot;
            multipliers[i - k - 1] = factor;
            row[k] = 0.0;
            if (factor == 0.0) continue;
            for (Eigen::Index j = k + 1; j <= ju; ++j) row[j] -= factor * pivotRow[j];
        }
    }
    return true;
}

void BandedLU::solveInPlace(Eigen::VectorXd& b) const
{
    double* x = b.data();
    for (Eigen::Index k = 0; k < n_; ++k) {
        const Eigen::Index p = pivot_[static_cast<std::size_t>(k)];
        if (p != k) std::swap(x[k], x[p]);
        const Eigen::Index lastRow = std::min(n_ - 1, k + kl_);
        const double* multipliers = lower_.data() + k * kl_;
        const double xk = x[k];
        for (Eigen::Index i = k + 1; i <= lastRow; ++i) x[i] -= multipliers[i - k - 1] * xk;
    }
    for (Eigen::Index k = n_ - 1; k >= 0; --k) {
        const double* row = rowPointer(k);
        const Eigen::Index lastCol = lastColumn_[static_cast<std::size_t>(k)];
        double sum = x[k];
        for (Eigen::Index j = k + 1; j <= lastCol; ++j) sum -= row[j] * x[j];
        x[k] = sum / row[k];
    }
}

}  // namespace dropletFiber
