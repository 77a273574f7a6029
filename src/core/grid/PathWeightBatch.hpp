// PathWeightBatch: PathWeight::omegaFromOffset for all nodes of a parcel's bounding box at
// once, the deposit's batched node loop for CPUs with AVX2 + FMA (KernelBuild.hpp). The
// common regime of eq. 23 (regime C, closed form with scaled erfc) is evaluated four nodes
// at a time without data-dependent branches (PathIntegralClosedForm.hpp); the ~1 node per
// parcel in the rare regimes A and B goes to PathWeight::integralAlongPath, the per-node
// code.
//
// Why: in the per-node code the regime choices are mispredicted ~2.7 times per weighted
// node, a third of the deposit's time (docs/performance.md). With four lanes the
// branch-free form pays for its extra work (3 exponentials per node instead of ~2, selects
// and gathers); with SSE2's two lanes it does not, hence it runs only where AVX2 is there.
//
// Result: omega of each node as PathWeight::omega gives it, to ~3e-15 relative of the
// parcel's largest weight (inline exp and erfc within ~1 ulp of libm; PathWeightBatchTest),
// including the negligible-weight cut of PathWeight::limitTo. Where that largest weight is
// itself tiny (Gaussian exponents E of a few hundred: kernels far narrower than a cell) up
// to ~E 1.1e-16: exp(-E) conditions the one-ulp difference between the exponent rounded
// with FMA (here) and without (the per-node code of a portable build).
#pragma once

#include "grid/PathWeight.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace dropletFiber
{

class PathWeightBatch
{
public:
    // Nodes per lane vector: counts passed to omegas() are multiples of this.
    static constexpr std::size_t laneCount = 4;
    // Boxes of fewer nodes go node by node: there the batched loop's fixed cost (stage
    // lists, padding to whole lanes) outweighs its gain (depositionBench, 2D: 336 vs 300 ns
    // per parcel at 5.4 nodes per box, 393 vs 490 ns at 11; threshold 8 was the best of
    // 6, 8, 10, 12, 16 at 5, 11 and 19 nodes per box).
    static constexpr std::size_t minimumBoxNodes = 8;

    // True when this build has the batched code and this CPU has AVX2 and FMA (and the
    // operating system saves their registers); asked once, the answer is kept.
    static bool cpuSupported();

    // omega[n] for the nodes that project to lambdaM[n] on the moving path's line at squared
    // distance d0Squared[n] (PathWeight::project). count must be a multiple of laneCount:
    // pad with d0Squared >= reach^2 (those give 0). Only where cpuSupported() (throws
    // std::logic_error otherwise: the caller chooses the per-node code there).
    void omegas(const PathWeight& path, const double* lambdaM, const double* d0Squared, double* omega,
                std::size_t count);

    // The deposit's use: omega of every node of the index box [lo, hi] (i fastest) of a grid
    // with node coordinates x[i], y[j], z[k], for the moving path `path` that starts at
    // `start`: the projection (PathWeight::project) and omegas(), both compiled for AVX2 +
    // FMA. Returns the box's node count values, valid until the next call. Only where
    // cpuSupported().
    const double* boxOmegas(const PathWeight& path, const Eigen::Vector3d& start, const double* x,
                            const double* y, const double* z, const std::array<int, 3>& lo,
                            const std::array<int, 3>& hi);

private:
    // Throws std::logic_error naming the caller unless cpuSupported().
    static void requireCpu(const char* caller);

    // Working memory, reused from parcel to parcel: the stages of omegas(), and for
    // boxOmegas() each node's projection on the path line, squared distance from it, omega.
    std::vector<double> values_;
    std::vector<std::uint32_t> indices_;
    std::vector<double> boxLambda_;
    std::vector<double> boxDistanceSquared_;
    std::vector<double> boxOmega_;
};

} // namespace dropletFiber
