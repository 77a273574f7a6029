// CaptureLimit: depletion of the spray by the fibers, the mass the fibers capture taken
// from the parcels that carried it (docs/model.md sec. 7, eqs. P12-P15, P18). Per time step,
// after the step's deposit is committed (DensityGrid::commitStep) and eq. 9 evaluated:
//
//  1. Demand (P12). A collision sample reads rho by multilinear interpolation of its cell's
//     corner densities; its captured mass m_s (eq. 9) is split over the corners in
//     proportion to (corner weight x corner density), d_sc = m_s w_c rho_c / sum w rho
//     (attributeSample), and added per node: d_n = sum of the d_sc at node n (addDemand).
//  2. Limit (P13). Eq. 9 read the window's mass per step at the node, s_n (its mean over
//     the window's steps); this step's parcels hold h_n there (DensityGrid::lastStepValue,
//     the newest committed step). Each sample's part intercepts the fraction d_sn / s_n of
//     the node's droplets over the step, independently of the others; limit() sets per node
//         f_n = 1 - prod_s (1 - min(1, d_sn / s_n))   taken fraction of h_n (0 where
//               s_n = 0): exp(-x_n) for many thin fibers, x_n = d_n / s_n the step's
//               optical depth (the droplets survive the step's rate); 1 where one sample
//               alone sweeps more than the node holds
//         g_n = f_n h_n / d_n   granted ratio (> 1 where this step holds more than
//                               the mean: eq. 9 is met in the mean over steps, to O(x_n))
//     and a sample's mass becomes sum_c d_sc g_{n_c} (grantedMass), its momentum that
//     times the sample's droplet velocity. Captured = sum_n f_n h_n <= sum_n h_n. In a
//     uniform dense region the survival is exact at any time step; where the rate
//     changes within a step's reach (a mat's faces) a parcel passes more by Var(x) / 2
//     per step (P18), first order in dt.
//  3. Removal (P14). Parcel p, which deposited w_pn F_p of its mass on node n (the
//     deposit's weight times the part of the step inside the box), loses the fraction
//         c_p = sum_n w_pn F_p f_n
//     of its droplets (capturedFraction; nParticle *= 1 - c_p, droplet size and velocity
//     unchanged). Removed = sum_p c_p m_p = sum_n f_n h_n: the mass
//     the fibers capture equals the mass leaving the spray, to round-off.
//
// The averaging window is not changed: it holds what was deposited (the window's later
// steps see the depleted parcels).
//
// Parallel runs (grid blocks, DensityGrid.hpp): demand at a node is kept by its owner
// (takeForeignDemand -> send -> addDemand); limit() runs on each block over its owned
// nodes; g_n of remote corners is asked of their owners (grantedRatio there,
// setGrantedRatio here); c_p is a sum over nodes, so each block evaluates the part over
// the nodes it owns for every parcel whose deposit box (DensityGrid::depositBox) meets its
// takenBox(), and the parts of one parcel from several blocks add up (clamp the sum to 1);
// or a block imports the owners' f_n (takenFractions -> setTakenFraction) for the nodes its
// parcels' deposit boxes reach and evaluates whole c_p itself.
#pragma once

#include "collision/CollisionMass.hpp"
#include "grid/DensityGrid.hpp"
#include "grid/MultilinearWeights.hpp"
#include "grid/SparseNodeValues.hpp"

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace dropletFiber
{

// One collision sample's captured mass split over the nodes that formed its density
// (P12): corners with no density get nothing and are left out.
struct SampleCapture
{
    int count = 0;                           // nodes with a share
    std::array<std::size_t, 8> node{};       // global flat node indices
    std::array<double, 8> mass{};            // d_sc, kg; their sum is the sample's m_coll
    Eigen::Vector3d velocity{0.0, 0.0, 0.0}; // droplet velocity at the sample (eq. 7)
};

// A segment's eq. 9 sample by sample, each with its attribution.
struct SegmentCapture
{
    SegmentCollision collision;         // the paper's result (before the limit)
    std::vector<SampleCapture> samples; // those inside the grid with rho > 0
};

// Per node mass (demand sent to a node's owner).
struct NodeMass
{
    std::size_t node = 0;
    double mass = 0.0;
};

// What limit() found on a block; sums add up across blocks.
struct CaptureLimitReport
{
    std::int64_t nodesDemanded = 0; // nodes with demand > 0
    std::int64_t nodesLimited = 0;  // of which demand > the window's mass per step (f_n = 1)
    double massDemanded = 0.0;      // sum d_n (eq. 9 without the limit), kg
    double massGranted = 0.0;       // sum f_n h_n: captured, and removed from the spray, kg

    CaptureLimitReport& operator+=(const CaptureLimitReport& other);
};

// P12 for one sample of mass sampleMass at a point whose cell corners (corners) have the
// window sums cornerTotals (nQuantities per corner, as for DensityGrid::interpolated).
SampleCapture attributeSample(const DensityGrid& grid, const CornerWeights& corners,
                              const double* cornerTotals, double sampleMass, const Eigen::Vector3d& velocity);

// P12 over the corners this grid owns (a block's part of attributeSample): massShare is
// the sample's mass over the whole grid's interpolated mass sum, m_s / Sigma (Sigma: the
// sums of DensityGrid::addOwnedCornerSums over the blocks owning the corners, entry
// quantityMass), so corner c gets massShare x its part of Sigma (densityParts). Summed over
// the blocks owning a sample's corners, these are attributeSample's demands (to round-off:
// (m_s / Sigma) part instead of m_s (part / Sigma)); the whole grid gives all of them.
SampleCapture attributeOwnedCorners(const DensityGrid& grid, const CornerWeights& corners, double massShare,
                                    const Eigen::Vector3d& velocity);

// Eq. 9 for the segment from a to b with every sample attributed (P12), on a grid that
// owns every corner the samples read (serial runs; a block reads remote corners itself
// and calls attributeSample). collision is collisionMass(grid, ...)'s result to the bit.
SegmentCapture segmentCapture(const DensityGrid& grid, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                              double fiberRadius, const Eigen::Vector3d& segmentVelocity, double dt,
                              const CollisionOptions& options = CollisionOptions{});

class CaptureLimit
{
public:
    // Forgets the previous step.
    void clear();

    // --- 1. demand (any node; a block sends the foreign part to the owners) -----------------
    void addDemand(const SampleCapture& sample);
    void addDemand(const SegmentCapture& segment);
    void addDemand(std::size_t node, double mass);
    // The demand at nodes the grid does not own, moved out, in node order: each addDemand
    // call's part apart (the owner multiplies their survivals, P13), in the order added.
    std::vector<NodeMass> takeForeignDemand(const DensityGrid& grid);

    // --- 2. the limit, on the owner ------------------------------------------------------------
    // f_n and g_n of every node with demand, from the grid's newest committed step. Throws
    // std::logic_error if demand at a node the grid does not own is left.
    CaptureLimitReport limit(const DensityGrid& grid);
    // g_n of a node with demand (limit() on its owner, or setGrantedRatio); throws
    // std::out_of_range for a node without one.
    double grantedRatio(std::size_t node) const;
    // g_n of a node owned elsewhere (its owner's answer).
    void setGrantedRatio(std::size_t node, double ratio);
    // The sample's mass after the limit: sum_c d_sc g_{n_c}; momentum = that * velocity.
    double grantedMass(const SampleCapture& sample) const;
    // The segment's mass and momentum after the limit.
    SegmentCollision granted(const SegmentCapture& segment) const;

    // --- 3. removal -------------------------------------------------------------------------------
    // f_n (0 at nodes without demand).
    double takenFraction(std::size_t node) const;
    // f_n <- q f_n at an owned node (discrete hits: q_n = realised / granted mass,
    // RealisedCapture.hpp; f_n may then exceed 1, c_p stays <= 1); a node left at 0 is
    // dropped.
    void scaleTakenFraction(std::size_t node, double q);
    // The nodes with f_n > 0 known here and their f_n (NodeMass::mass holds f_n), in node order.
    std::vector<NodeMass> takenFractions() const;
    // f_n of a node owned elsewhere (its owner's takenFractions()): a block that has them
    // for every node its parcels' deposit boxes reach evaluates their whole c_p itself,
    // instead of sending them to the owners.
    void setTakenFraction(std::size_t node, double fraction, const std::array<int, 3>& gridNodes);
    // The owned nodes with f_n > 0 (a block tells the others; empty: nothing to remove here).
    const IndexBox& takenBox() const { return takenBox_; }
    // True when the box (grid indices) may hold a node with f_n > 0: it meets a brick of
    // brickSize^3 nodes that holds one.
    bool mayTake(const IndexBox& box) const;
    // c_p over the nodes this block owns (the whole grid: c_p itself), in [0, 1]. The same
    // parcel and dt as deposited this step. A parcel whose deposit nodes meet no brick
    // with f_n > 0 costs a clip and a box, not its weights; the others' weights are
    // evaluated at the nodes with f_n > 0 only (DensityGrid::depositedShare, sparse).
    double capturedFraction(DensityGrid& grid, const Parcel& parcel, double dt) const;
    static constexpr int brickSize = 4;

private:
    // False when the parcel's deposit cannot reach a node with f_n > 0 (a cheap bound from
    // r_max, checked before its weights are evaluated).
    bool mayReach(const GridSpec& spec, const KernelSettings& kernel, const Parcel& parcel, double dt) const;
    // Clears takenBrick_ (the bricks set only).
    void forgetTakenBricks();
    // f_n > 0 at the node: takenBox_ and its brick.
    void markTaken(std::size_t node, const std::array<int, 3>& nodes);
    std::size_t brickIndex(int i, int j, int k) const
    {
        return static_cast<std::size_t>(i)
            + bricks_[0] * (static_cast<std::size_t>(j) + bricks_[1] * static_cast<std::size_t>(k));
    }

    // Per node: the demand d_n and its parts d_sn, one per interceptor (addDemand call)
    struct NodeDemand
    {
        double total = 0.0;
        std::vector<double> parts;
    };
    // f_n = 1 - prod (1 - min(1, d_sn / s_n)) (P13)
    static double interceptedFraction(const std::vector<double>& parts, double supply);
    std::unordered_map<std::size_t, NodeDemand> demand_;
    std::unordered_map<std::size_t, double> granted_; // g_n
    std::unordered_map<std::size_t, double> taken_;   // f_n > 0, owned nodes
    // taken_ in node order with grid indices (capturedFraction's sums), built on first use
    // after taken_ changed; 40 bytes per node with f_n > 0.
    const SparseNodeValues& takenNodes() const;
    mutable SparseNodeValues takenNodes_;
    mutable bool takenNodesStale_ = true;
    std::array<int, 3> gridNodes_{}; // the grid's nodes per direction (limit, setTakenFraction)
    IndexBox takenBox_;
    std::array<std::size_t, 3> bricks_{};     // per direction, over the grid
    std::vector<unsigned char> takenBrick_;   // per brick of the grid: 1 when it holds f_n > 0
    std::vector<std::size_t> takenBrickList_; // the bricks set, to clear them
};

} // namespace dropletFiber
