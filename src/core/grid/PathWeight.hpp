// PathWeight: the path-integrated kernel weight omega_g of one grid node for a parcel
// that moves along a straight path during the step (docs/model.md eqs. 19-23):
//     omega_g = integral_{tau_1}^{tau_2} phi(|p + tau v dt - g|) dtau,
// tau in [0, 1] along the path, [tau_1, tau_2] = where the node is within the kernel's
// reach, clipped to [0, 1] (so nodes whose nearest path point lies beyond an end of the
// path, and paths that end inside the support, are handled by the same formula).
//
// Closed form (docs/model.md sec. 4): with the along-path coordinate lambda = tau L (L = |v dt|),
// lambda_m = the node's projection on the path line, d_0 = the distance of the node from
// that line, x = sqrt(gamma) (lambda - lambda_m):
//     omega_g = [ exp(-gamma d_0^2) / sqrt(gamma) * int_{x_1}^{x_2} exp(-x^2) dx
//                 - exp(-gamma reach^2) (lambda_2 - lambda_1) ] / L.
// Working in lambda (not tau) keeps L -> 0 finite: tau_min of eq. 21 diverges, lambda_m
// does not. The integral is evaluated three ways so that it stays accurate to round-off
// (see PathWeight.cpp): scaled erfc (long intervals; the Gaussians at the ends of the
// interval times exp(x^2) erfc(x), so no erf difference cancels), a Taylor series in the
// half-width (short intervals, including L -> 0), and a Gauss-Legendre rule on
// exp(-a) expm1(...) where the path only grazes the edge of the support (there the two
// terms above nearly cancel). A path shorter than 1e-12 reach is taken as a point at its
// midpoint: omega = phi(|midpoint - g|), the L -> 0 limit.
//
// Accuracy: agrees with adaptive quadrature of eq. 23 to 1e-10 relative (typically
// 1e-13), for L from 0 to many reaches and alpha from 0.3 to 1000 (PathWeightTest).
// Within a relative gap g = 1 - d^2/reach^2 < 1e-5 of the rim of the support the rounding
// of the inputs alone moves omega by ~1e-16/g relative (conditioning, not the method);
// such weights are ~exp(-alpha) g and do not matter for the mass.
//
// Geometry is plain 3D; a 2D grid passes vectors with the flat component zeroed.
#pragma once

#include "grid/ParcelKernel.hpp"

#include <Eigen/Core>

#include <algorithm>

namespace dropletFiber
{

class PathWeight
{
public:
    // The path runs from start to start + displacement during the step.
    PathWeight(const ParcelKernel& kernel, const Eigen::Vector3d& start, const Eigen::Vector3d& displacement);

    // Eq. 23 for a node at `node`; zero when the node is out of reach.
    double omega(const Eigen::Vector3d& node) const { return omegaFromOffset(node - start_); }

    // Same, from offset = node - start (the grid loop has it).
    double omegaFromOffset(const Eigen::Vector3d& offset) const
    {
        if (stationary_)
        {
            const double dSquared = (offset - halfDisplacement_).squaredNorm();
            return dSquared < cutoffSquared_ ? kernel_.phiOfSquaredDistance(dSquared) : 0.0;
        }
        const double lambdaM = direction_.dot(offset);
        const double d0Squared = (offset - lambdaM * direction_).squaredNorm();
        if (!(d0Squared < cutoffSquared_))
        {
            return 0.0;
        }
        return integralAlongPath(lambdaM, d0Squared) * inverseLength_;
    }

    // Nodes farther than `distance` from the path (line) get 0: their phi is below
    // exp(-gamma distance^2) everywhere on the path (DensityGrid::deposit, negligible weights).
    // distance >= reach: no effect.
    void limitTo(double distance) { cutoffSquared_ = std::min(reachSquared_, distance * distance); }

    // A moving path (not stationary()): the node at `offset` from the start projects to
    // lambdaM on the path line, at squared distance d0Squared from it (the operations of
    // omegaFromOffset; used by the batched deposit, PathWeightBatch).
    void project(const Eigen::Vector3d& offset, double& lambdaM, double& d0Squared) const
    {
        lambdaM = direction_.dot(offset);
        d0Squared = (offset - lambdaM * direction_).squaredNorm();
    }

    double length() const { return length_; }
    double cutoffSquared() const { return cutoffSquared_; }
    bool stationary() const { return stationary_; }
    const ParcelKernel& kernel() const { return kernel_; }

    // int phi dlambda over the part of the path within reach (metres), for a node at
    // distance sqrt(d0Squared) < reach from the path line, projecting to lambdaM on it.
    double integralAlongPath(double lambdaM, double d0Squared) const;

private:
    ParcelKernel kernel_;
    Eigen::Vector3d start_;
    Eigen::Vector3d halfDisplacement_;
    Eigen::Vector3d direction_{0.0, 0.0, 0.0};
    double length_ = 0.0;
    double inverseLength_ = 0.0;
    double reachSquared_ = 0.0;
    double cutoffSquared_ = 0.0; // reach^2, or less after limitTo
    double sqrtGamma_ = 0.0;
    double inverseSqrtGamma_ = 0.0;
    bool stationary_ = true;
};

} // namespace dropletFiber
