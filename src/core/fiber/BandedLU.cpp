#include "fiber/BandedLU.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace dropletFiber
{

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
    inverseDiagonal_.assign(static_cast<std::size_t>(n), 0.0);
}

void BandedLU::setPivotThreshold(double threshold)
{
    if (!(threshold > 0.0 && threshold <= 1.0))
    {
        throw std::invalid_argument("BandedLU: pivot threshold must be in (0, 1]");
    }
    pivotThreshold_ = threshold;
}

void BandedLU::assignMatrix(const BandedLU& other)
{
    n_ = other.n_;
    kl_ = other.kl_;
    ku_ = other.ku_;
    width_ = other.width_;
    band_ = other.band_; // same size: copies into the existing storage
    lower_.resize(static_cast<std::size_t>(n_ * kl_));
    pivot_.resize(static_cast<std::size_t>(n_));
    lastColumn_.resize(static_cast<std::size_t>(n_));
    inverseDiagonal_.resize(static_cast<std::size_t>(n_));
}

double BandedLU::coeff(Eigen::Index i, Eigen::Index j) const
{
    const Eigen::Index offset = j - i;
    if (offset < -kl_ || offset > kl_ + ku_)
        return 0.0;
    return rowPointer(i)[j];
}

namespace
{

// row[j] -= factor * pivotRow[j] for j in [first, last]: the elimination's inner loop.
// The two rows are different rows of the band (never alias): saying so lets the
// compiler vectorise without run-time overlap checks. Element by element, so the
// vector width does not change a single bit.
inline void subtractScaledRow(double* __restrict row, const double* __restrict pivotRow, double factor,
                              Eigen::Index first, Eigen::Index last)
{
    for (Eigen::Index j = first; j <= last; ++j)
        row[j] -= factor * pivotRow[j];
}

} // namespace

bool BandedLU::factorize()
{
    // ju: last column any row of U so far reaches (dgbtf2's JU). Rows below k hold
    // nothing right of max(ju, their own i + ku), so columns past ju need no update.
    Eigen::Index ju = 0;
    rowExchanges_ = 0;
    const Eigen::Index columnStride = width_ - 1; // A(i+1, j) is this far after A(i, j)
    for (Eigen::Index k = 0; k < n_; ++k)
    {
        const Eigen::Index lastRow = std::min(n_ - 1, k + kl_);
        double* pivotRow = rowPointer(k);
        // Pivot: the diagonal if it passes the threshold, else the largest |A(i, k)|,
        // i = k..lastRow (first one on ties).
        Eigen::Index p = k;
        double biggest = std::abs(pivotRow[k]);
        const double* entry = pivotRow + k;
        for (Eigen::Index i = k + 1; i <= lastRow; ++i)
        {
            entry += columnStride;
            const double candidate = std::abs(*entry);
            if (candidate > biggest)
            {
                biggest = candidate;
                p = i;
            }
        }
        if (biggest == 0.0)
            return false;
        if (std::abs(pivotRow[k]) >= pivotThreshold_ * biggest)
            p = k;
        pivot_[static_cast<std::size_t>(k)] = p;
        if (p != k)
            ++rowExchanges_;
        ju = std::max(ju, std::min(n_ - 1, p + ku_));
        lastColumn_[static_cast<std::size_t>(k)] = ju;
        if (p != k)
        {
            double* other = rowPointer(p);
            for (Eigen::Index j = k; j <= ju; ++j)
                std::swap(pivotRow[j], other[j]);
        }
        const double inversePivot = 1.0 / pivotRow[k];
        inverseDiagonal_[static_cast<std::size_t>(k)] = inversePivot;
        double* multipliers = lower_.data() + k * kl_; // row i's at i - k - 1
        for (Eigen::Index i = k + 1; i <= lastRow; ++i)
        {
            double* row = rowPointer(i);
            const double factor = row[k] * inversePivot;
            multipliers[i - k - 1] = factor;
            row[k] = 0.0;
            if (factor == 0.0)
                continue;
            subtractScaledRow(row, pivotRow, factor, k + 1, ju);
        }
    }
    return true;
}

void BandedLU::solveInPlace(Eigen::VectorXd& b) const
{
    double* x = b.data();
    for (Eigen::Index k = 0; k < n_; ++k)
    {
        const Eigen::Index p = pivot_[static_cast<std::size_t>(k)];
        if (p != k)
            std::swap(x[k], x[p]);
        const Eigen::Index lastRow = std::min(n_ - 1, k + kl_);
        const double* multipliers = lower_.data() + k * kl_;
        const double xk = x[k];
        for (Eigen::Index i = k + 1; i <= lastRow; ++i)
            x[i] -= multipliers[i - k - 1] * xk;
    }
    // Back substitution by columns (as LAPACK's dtbsv): once x_j is final it is taken
    // out of every row above that reaches column j. The rows' updates are independent,
    // unlike the row-by-row sum whose chain of dependent subtractions is the cost.
    // U's row i reaches column lastColumn_[i], which never decreases with i: the rows
    // reaching column j are a contiguous run first..j-1.
    Eigen::Index first = n_;
    for (Eigen::Index j = n_ - 1; j >= 0; --j)
    {
        x[j] *= inverseDiagonal_[static_cast<std::size_t>(j)]; // a division here would be
                                                               // on the critical path
        while (first > 0 && lastColumn_[static_cast<std::size_t>(first - 1)] >= j)
            --first;
        const double xj = x[j];
        for (Eigen::Index i = first; i < j; ++i)
            x[i] -= rowPointer(i)[j] * xj;
    }
}

} // namespace dropletFiber
