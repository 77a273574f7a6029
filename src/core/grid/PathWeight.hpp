// PathWeight: the path-integrated kernel weight omega_g of one grid node for a parcel
// that moves along a straight path during the step (MODEL.md eqs. 19-23):
//     omega_g = integral_{tau_1}^{tau_2} phi(|p + tau v dt - g|) dtau,
// tau in [0, 1] along the path, [tau_1, tau_2] = where the node is within the kernel's
// reach, clipped to [0, 1] (so nodes whose nearest path point lies beyond an end of the
// path, and paths that end inside the support, are handled by the same formula).
//
// Closed form (MODEL.md): with the along-path coordinate lambda = tau L (L = |v dt|),
// lambda_m = the node's projection on the path line, d_0 = the distance of the node from
// that line, x = sqrt(gamma) (lambda - lambda_m):
//     omega_g = [ exp(-gamma d_0^2) / sqrt(gamma) * int_{x_1}^{x_2} exp(-x^2) dx
//                 - exp(-gamma reach^2) (lambda_2 - lambda_1) ] / L.
// Working in lambda (not tau) keeps L -> 0 finite: tau_min of eq. 21 diverges, lambda_m
// does not. The integral is evaluated three ways so that it stays accurate to round-off:
// scaled erfc (regime C, long intervals: the Gaussians at the ends of the interval times
// exp(x^2) erfc(x), so no erf difference cancels; PathIntegralClosedForm.hpp, branch-free),
// a Taylor series in the half-width (regime B, short intervals, including L -> 0), and a
// Gauss-Legendre rule on exp(-a) expm1(...) where the path only grazes the edge of the
// support (regime A, there the two terms above nearly cancel); A and B in PathWeight.cpp.
// A path shorter than 1e-12 reach is taken as a point at its midpoint:
// omega = phi(|midpoint - g|), the L -> 0 limit.
//
// Two entry points with the same result to the bit: omega() for one node, and omegas()
// for many (the deposit), which evaluates regime C two nodes at a time without branches
// and only the ~1 node per parcel in regimes A or B with the scalar code.
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
#include "grid/PathIntegralClosedForm.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <vector>

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
            return kernel_.phiSquared((offset - halfDisplacement_).squaredNorm());
        }
        double lambdaM, d0Squared;
        project(offset, lambdaM, d0Squared);
        if (!(d0Squared < reachSquared_))
        {
            return 0.0;
        }
        return integralAlongPath(lambdaM, d0Squared) * inverseLength_;
    }

    // A moving path (not stationary()): the node at `offset` from the start projects to
    // lambdaM on the path line, at squared distance d0Squared from it.
    void project(const Eigen::Vector3d& offset, double& lambdaM, double& d0Squared) const
    {
        // Written out (not Eigen's dot) so that the order of the operations is fixed.
        lambdaM = (direction_.x() * offset.x() + direction_.y() * offset.y()) + direction_.z() * offset.z();
        const double ex = offset.x() - lambdaM * direction_.x();
        const double ey = offset.y() - lambdaM * direction_.y();
        const double ez = offset.z() - lambdaM * direction_.z();
        d0Squared = (ex * ex + ey * ey) + ez * ez;
    }

    // Working memory of omegas(), reused from parcel to parcel.
    struct Scratch
    {
        std::vector<double> values;
        std::vector<std::uint32_t> indices;
    };

    // omega for `count` nodes of a moving path from their project() values: the same
    // bits as omegaFromOffset, node by node. count must be a multiple of laneCount (pad
    // with d0Squared >= reach^2: those give 0).
    void omegas(const double* lambdaM, const double* d0Squared, double* omega, std::size_t count,
                Scratch& scratch) const;

    double length() const { return length_; }
    bool stationary() const { return stationary_; }
    const ParcelKernel& kernel() const { return kernel_; }

    // int phi dlambda over the part of the path within reach (metres), for a node at
    // distance sqrt(d0Squared) from the path line (0 from reach on), projecting to lambdaM.
    double integralAlongPath(double lambdaM, double d0Squared) const;

private:
    // Regimes A and B (the nodes PathIntegralClosedForm flags).
    double exactIntegral(double lambdaM, double d0Squared) const;

    ParcelKernel kernel_;
    Eigen::Vector3d start_;
    Eigen::Vector3d halfDisplacement_;
    Eigen::Vector3d direction_{0.0, 0.0, 0.0};
    double length_ = 0.0;
    double inverseLength_ = 0.0;
    double reachSquared_ = 0.0;
    double sqrtGamma_ = 0.0;
    double inverseSqrtGamma_ = 0.0;
    bool stationary_ = true;
    PathIntegralClosedForm closedForm_;
};

} // namespace dropletFiber
