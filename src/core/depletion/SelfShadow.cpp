#include "depletion/SelfShadow.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <limits>

namespace dropletFiber
{

Eigen::Vector3d stripAcrossFlow(double stripWidth, const Eigen::Vector3d& segment,
                                const Eigen::Vector3d& relativeVelocity)
{
    Eigen::Vector3d normal = segment.cross(relativeVelocity);
    const double largest = normal.cwiseAbs().maxCoeff();
    if (!(largest > 0.0) || !(stripWidth > 0.0) || !std::isfinite(largest))
    {
        return Eigen::Vector3d::Zero();
    }
    normal /= largest; // no under- or overflow in the squares
    return stripWidth * normal.cwiseProduct(normal) / normal.squaredNorm();
}

namespace
{
// A node's dual width along a direction of `nodes` nodes, in spacings: half on a face.
double dualWidth(int index, int nodes)
{
    return index == 0 || index == nodes - 1 ? 0.5 : 1.0;
}

// The hats' mass matrix along a direction, in spacings: int hat_i hat_j / h.
double massMatrix(int i, int j, int nodes)
{
    if (i != j)
    {
        return 1.0 / 6.0;
    }
    return i == 0 || i == nodes - 1 ? 1.0 / 3.0 : 2.0 / 3.0;
}
} // namespace

std::array<double, 8> selfShadow(const GridSpec& spec, const CornerWeights& corners,
                                 const Eigen::Vector3d& strip)
{
    std::array<double, 8> sigma{};
    int rank = 0; // the bit of an active direction in the corner index (multilinearWeights)
    for (int d = 0; d < 3; ++d)
    {
        const double q = strip[d];
        if (spec.flat(d))
        {
            // Uniform across the layer: f = q / T at every lane, its mean q / T
            for (int c = 0; c < corners.count; ++c)
            {
                sigma[static_cast<std::size_t>(c)] += q > 0.0 ? 0.5 * q / spec.spacing(d) : 0.0;
            }
            continue;
        }
        const int bit = rank++;
        if (!(q > 0.0))
        {
            continue;
        }
        // The sample's fraction towards the upper node along d: the marginal of the weights
        double upper = 0.0;
        for (int c = 0; c < corners.count; ++c)
        {
            upper += ((c >> bit) & 1) != 0 ? corners.weight[static_cast<std::size_t>(c)] : 0.0;
        }
        const int n = spec.nodes[d];
        const std::array<int, 2> index{{corners.lowerCorner[d], corners.lowerCorner[d] + 1}};
        const std::array<double, 2> weight{{1.0 - upper, upper}};
        std::array<double, 2> mean{};
        for (int side = 0; side < 2; ++side)
        {
            // (M phi)_i / H_i with phi_j = q w_j / (h H_j): the fiber's lane depth averaged
            // over node i's hat, per unit q / h
            double sum = 0.0;
            for (int other = 0; other < 2; ++other)
            {
                sum += weight[static_cast<std::size_t>(other)]
                    * massMatrix(index[static_cast<std::size_t>(side)],
                                 index[static_cast<std::size_t>(other)], n)
                    / dualWidth(index[static_cast<std::size_t>(other)], n);
            }
            mean[static_cast<std::size_t>(side)] = sum / dualWidth(index[static_cast<std::size_t>(side)], n);
        }
        const double scale = 0.5 * q / spec.spacing(d);
        for (int c = 0; c < corners.count; ++c)
        {
            sigma[static_cast<std::size_t>(c)] += scale * mean[static_cast<std::size_t>((c >> bit) & 1)];
        }
    }
    return sigma;
}

double shadowedDepth(double fraction, double sigma)
{
    if (fraction >= 1.0)
    {
        return std::numeric_limits<double>::infinity();
    }
    if (!(sigma > 0.0))
    {
        return -std::log1p(-fraction); // a bare part: P13, its square within the step only
    }
    // -ln(1 - a) - a^2 / 2 = a + a^3 / 3 + ...: P13's product per step would add a^2 / 2,
    // the part of the fiber's own square within one step, which sigma counts whole
    return -std::log1p(-fraction) - 0.5 * fraction * fraction + fraction * sigma;
}

} // namespace dropletFiber
