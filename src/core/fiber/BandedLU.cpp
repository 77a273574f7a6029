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
}

double BandedLU::coeff(Eigen::Index i, Eigen::Index j) const
{
    const Eigen::Index offset = j - i;
    if (offset < -kl_ || offset > kl_ + ku_) return 0.0;
    return at(i, j);
}

bool BandedLU::factorize()
{
    for (Eigen::Index k = 0; k < n_; ++k) {
        const Eigen::Index lastRow = std::min(n_ - 1, k + kl_);
        const Eigen::Index lastCol = std::min(n_ - 1, k + kl_ + ku_);
        Eigen::Index p = k;
        double biggest = std::abs(at(k, k));
        for (Eigen::Index i = k + 1; i <= lastRow; ++i) {
            if (std::abs(at(i, k)) > biggest) {
                biggest = std::abs(at(i, k));
                p = i;
            }
        }
        pivot_[static_cast<std::size_t>(k)] = p;
        if (biggest == 0.0) return false;
        if (p != k) {
            for (Eigen::Index j = k; j <= lastCol; ++j) std::swap(at(k, j), at(p, j));
        }
        const double inversePivot = 1.0 / at(k, k);
        for (Eigen::Index i = k + 1; i <= lastRow; ++i) {
            const double factor = at(i, k) * inversePivot;
            lower_[static_cast<std::size_t>(k * kl_ + (i - k - 1))] = factor;
            at(i, k) = 0.0;
            if (factor == 0.0) continue;
            for (Eigen::Index j = k + 1; j <= lastCol; ++j) at(i, j) -= factor * at(k, j);
        }
    }
    return true;
}

void BandedLU::solveInPlace(Eigen::VectorXd& b) const
{
    for (Eigen::Index k = 0; k < n_; ++k) {
        const Eigen::Index p = pivot_[static_cast<std::size_t>(k)];
        if (p != k) std::swap(b(k), b(p));
        const Eigen::Index lastRow = std::min(n_ - 1, k + kl_);
        for (Eigen::Index i = k + 1; i <= lastRow; ++i) {
            b(i) -= lower_[static_cast<std::size_t>(k * kl_ + (i - k - 1))] * b(k);
        }
    }
    for (Eigen::Index k = n_ - 1; k >= 0; --k) {
        const Eigen::Index lastCol = std::min(n_ - 1, k + kl_ + ku_);
        double sum = b(k);
        for (Eigen::Index j = k + 1; j <= lastCol; ++j) sum -= at(k, j) * b(j);
        b(k) = sum / at(k, k);
    }
}

}  // namespace dropletFiber
