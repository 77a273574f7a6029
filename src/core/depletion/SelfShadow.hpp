// SelfShadow: a fiber's depth on the grid's nodes made to take its strip from the lanes that
// cross it (docs/model.md sec. 7, thick fibers, P21). A fiber's demand reaches the node
// columns across the flow by hat weights, so a lane crossing it collects the smeared depth
// f = sum_n phi_n hat_n (phi_n: the fiber's fraction of column n over its crossing) where it
// should lose the fraction f: it must collect -ln(1 - f) = f + f^2 / 2 + ... Per sample and
// node the part's depth is scaled by 1 + sigma, sigma half the hat-weighted mean of the
// fiber's own f over the node's column (its mass matrix row, (M phi)_n / (2 H_n), H_n the
// column's dual width), so that the lanes collect the integral of f + f^2 / 2 and each lane
// loses its strip to second order in c / h. Per grid direction across the flow, from the
// sample's corner weights alone: no neighbour's data.
#pragma once

#include "grid/GridSpec.hpp"
#include "grid/MultilinearWeights.hpp"

#include <Eigen/Core>

#include <array>

namespace dropletFiber
{

// The fiber's strip across the flow per grid direction, q_d = c n_d^2: c = 2 (r_F + r_p),
// n the unit normal to the segment and to the droplets' velocity relative to it (the
// direction across which the strip is narrow). Zero where the two are parallel (no strip).
Eigen::Vector3d stripAcrossFlow(double stripWidth, const Eigen::Vector3d& segment,
                                const Eigen::Vector3d& relativeVelocity);

// sigma per corner of the sample's cell (multilinearWeights' corner order): the sum over
// the directions d of q_d / 2 times the mean over corner c's hat along d of the fiber's
// hat profile along d per unit strip, sum_c' w_c' M_cc' / (H_c H_c') (M the 1D mass
// matrix of the hats: 2h/3 inside, h/3 at a face, h/6 beside; H the dual widths, h or
// h/2). Exact for a strip normal to a grid direction; an oblique strip weighs the
// directions by n_d^2. A flat direction (one node layer) is uniform across its thickness T:
// q_d / (2 T) for every corner.
std::array<double, 8> selfShadow(const GridSpec& spec, const CornerWeights& corners,
                                 const Eigen::Vector3d& strip);

// A sample's part of a node's optical depth for the step, a = d_sn / s_n the fraction of
// the node's droplets it intercepts and sigma > 0 its self-shadow: a (1 + sigma) to second
// order (the lanes' mean over the crossing, whatever the step), with the higher orders of
// -ln(1 - a) so that a part tending to the whole node tends to saturation; infinity
// for a >= 1 (one interceptor takes all). sigma = 0, a part without its fiber's strip
// (CaptureLimit::addDemand(node, mass)): P13's -ln(1 - a).
double shadowedDepth(double fraction, double sigma);

} // namespace dropletFiber
