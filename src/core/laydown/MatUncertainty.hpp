// MatUncertainty: the mat's figures with their statistical errors (docs/model.md sec. 11,
// P60-P61). Every computed fiber laid is an independent draw of where its physical fibers
// land, so a sum over the fibers' contributions c_i has the variance sum c_i^2 (MatMap's
// error sums). From them: a cell's area weight and LOI with their standard errors, the
// across-width profile over complete rows with each column's error, and the profile's
// coefficient of variation split into what counting noise alone gives and the mat's real
// non-uniformity:
//   E[s^2] = s_real^2 + mean_j var_j - var(mean)     (s: the population sd across columns)
// so s_real^2 = s^2 - noise^2, noise^2 = mean_j var_j - var(mean); the estimate of s^2 has
// itself the spread ds^2 = sqrt(2 noise^4 / n + 4 s_real^2 noise^2 / n) (Gaussian columns),
// and the real CoV is given with a two-sigma upper bound.
#pragma once

#include "laydown/MatMap.hpp"

#include <vector>

namespace dropletFiber
{

// An LOI = b / (g + b) and its standard error by the delta method, from the variances of
// g and b and their covariance.
struct ValueWithError
{
    double value = 0.0;
    double error = 0.0;
};
ValueWithError lossOnIgnition(double glass, double binder, double varGlass, double varBinder,
                              double covariance);

// A cell's glass area weight [kg/m^2] and LOI [-] with their errors.
ValueWithError cellAreaWeight(const MatCell& cell, double area);
ValueWithError cellLoi(const MatCell& cell);

// The profile across the width over rows [rowFrom, rowTo]: per column the glass area
// weight and LOI with their errors, and the variance of the columns' mean area weight.
// A fiber whose footprint reaches past the rows counts its whole column part in the
// errors of the rows' edge cells: the errors are exact for rows the fibers' footprints lie
// within, an upper bound at the ends.
struct AcrossProfile
{
    std::vector<ValueWithError> areaWeight;
    std::vector<ValueWithError> loi;
    double meanVariance = 0.0;
    ValueWithError loiAll; // the rows' LOI over the whole width
};
AcrossProfile acrossProfileWithErrors(const MatMap& map, long rowFrom, long rowTo);

// The profile's coefficient of variation, observed and split (above).
struct NonUniformity
{
    double mean = 0.0;      // kg/m^2, the columns' mean
    double observed = 0.0;  // CoV as measured
    double noise = 0.0;     // CoV counting noise alone gives
    double real = 0.0;      // CoV of the mat itself, estimated (0 when noise explains all)
    double realUpper = 0.0; // its two-sigma upper bound
};
NonUniformity nonUniformity(const AcrossProfile& profile);

} // namespace dropletFiber
