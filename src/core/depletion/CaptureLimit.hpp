// CaptureLimit: depletion of the spray by the fibers, the mass the fibers capture taken
// from the parcels that carried it (docs/model.md sec. 7, eqs. P12-P15, P18, P21). Per time step,
// after the step's deposit is committed (DensityGrid::commitStep) and eq. 9 evaluated:
//
//  1. Demand (P12). A collision sample reads rho by multilinear interpolation of its cell's
//     corner densities; its captured mass m_s (eq. 9) is split over the corners in
//     proportion to (corner weight x corner density), d_sc = m_s w_c rho_c / sum w rho
//     (attributeSample), and added per node: d_n = sum of the d_sc at node n (addDemand).
//  2. Optical depth (P13). Eq. 9 read the window's mass per step at the node, s_n (its
//     mean over the window's steps). Each sample's part d_sn / s_n is the fraction of the
//     node's droplets it intercepts over the step, independently of the others; limit()
//     sets per node the step's optical depth
//         x_n = -ln prod_s (1 - d_sn / s_n)   (sum_s d_sn / s_n = d_n / s_n for thin fibers;
//                                              0 where s_n = 0), or "saturated" where one
//                                              sample alone sweeps more than the node holds
//     A sample given its fiber's strip (attributeSample's strip) adds a (1 + sigma) instead of
//     -ln(1 - a), to second order: the fiber's self-shadow (P21, SelfShadow.hpp), so that
//     the lanes crossing a fiber thick against the spacing lose its strip.
//  3. Removal, per parcel (P14). Parcel p, which deposited w_pn F_p of its mass on node n
//     (the deposit's weight times the part of the step inside the box), crosses the depth
//     X_p = F_p sum_n w_pn x_n over the unsaturated nodes and loses its share on the
//     saturated ones, A_p = F_p sum_n w_pn there:
//         c_p = 1 - (1 - A_p) exp(-X_p)                         (capturedFraction)
//     of its droplets (nParticle *= 1 - c_p, droplet size and velocity unchanged). Its loss
//     is attributed to the nodes: r_pn = m_p F_p w_pn on a saturated node, and
//     r_pn = m_p (1 - A_p)(1 - exp(-X_p)) F_p w_pn x_n / X_p on the others (remove); the
//     node's removed mass R_n = sum_p r_pn. A parcel keeps exp(-sum w x), not
//     sum w exp(-x): no error where the rate changes within its step's reach (a mat's
//     faces); what is left is second order in dt (docs/model.md sec. 7, P18).
//  4. Grant. g_n = R_n / d_n (grant) and a sample's mass becomes sum_c d_sc g_{n_c}
//     (grantedMass), its momentum that times the sample's droplet velocity. Captured =
//     sum_n R_n = sum_p c_p m_p, removed: to round-off.
//
// The averaging window is not changed: it holds what was deposited (the window's later
// steps see the depleted parcels).
//
// Parallel runs (grid blocks, DensityGrid.hpp): demand at a node is kept by its owner
// (takeForeignDemand -> send -> addDemand); limit() runs on each block over its owned
// nodes. A_p and X_p are sums over nodes: each block evaluates their parts over the nodes
// it owns (reach) for every parcel whose deposit box (DensityGrid::depositBox) meets its
// takenBox(); the parts of one parcel from several blocks add up on the parcel's
// processor, which forms c_p and sends (A_p, X_p) back to the blocks holding its copies;
// each block then attributes the removal to its nodes (remove) and grants (grant), and
// answers the samples' owners with their granted parts.
//
// Discrete hits: where the fibers realise at node n q_n times the granted R_n, the
// parcels must lose sum_n r_pn q_n instead: scaleRemoval(node, q_n) on the owner, then
// removedFraction() over the blocks (the parts add up) replaces c_p; with every q_n = 1
// (expected hits) it is c_p to round-off. A parcel whose parts ask more than it holds
// (sum_n r_pn q_n > m_p) gives m_p: its shortfall is spread over its parts
// (addShortfall) and the node's realised mass is cut by it (unremovedShare, P33).
#pragma once

#include "collision/CollisionMass.hpp"
#include "depletion/FixedPointSum.hpp"
#include "grid/DensityGrid.hpp"
#include "grid/DepositedShare.hpp"
#include "grid/MultilinearWeights.hpp"
#include "grid/SparseNodeValues.hpp"

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <utility>
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
    std::array<double, 8> shadow{};          // sigma of each part (P21, SelfShadow.hpp); 0: none
};

// A segment's eq. 9 sample by sample, each with its attribution.
struct SegmentCapture
{
    SegmentCollision collision;         // the paper's result (before the limit)
    std::vector<SampleCapture> samples; // those inside the grid with rho > 0
};

// Per node mass (demand sent to a node's owner): one interceptor's part, asked by
// `interceptors` physical fibers at that place (a computed fiber's weight).
struct NodeMass
{
    std::size_t node = 0;
    double mass = 0.0;
    double shadow = 0.0;       // the part's sigma (P21)
    double interceptors = 1.0; // the physical fibers asking it (P40)
};

// What limit() found on a block; sums add up across blocks.
struct CaptureLimitReport
{
    std::int64_t nodesDemanded = 0; // nodes with demand > 0
    std::int64_t nodesLimited = 0;  // of which demand > the window's mass per step (x_n > 1)
    double massDemanded = 0.0;      // sum d_n (eq. 9 without the limit), kg
    double massGranted = 0.0;       // sum R_n: captured, and removed from the spray, kg
    double excessDemanded = 0.0;    // sum of d_n - s_n over the limited nodes, kg

    CaptureLimitReport& operator+=(const CaptureLimitReport& other);
};

// P12 for one sample of mass sampleMass at a point whose cell corners (corners) have the
// window sums cornerTotals (nQuantities per corner, as for DensityGrid::interpolated).
// strip: the fiber's strip across the flow (stripAcrossFlow, P21); zero: no self-shadow.
SampleCapture attributeSample(const DensityGrid& grid, const CornerWeights& corners,
                              const double* cornerTotals, double sampleMass, const Eigen::Vector3d& velocity,
                              const Eigen::Vector3d& strip = Eigen::Vector3d::Zero());

// P12 over the corners this grid owns (a block's part of attributeSample): massShare is
// the sample's mass over the whole grid's interpolated mass sum, m_s / Sigma (Sigma: the
// sums of DensityGrid::addOwnedCornerSums over the blocks owning the corners, entry
// quantityMass), so corner c gets massShare x its part of Sigma (densityParts). Summed over
// the blocks owning a sample's corners, these are attributeSample's demands (to round-off:
// (m_s / Sigma) part instead of m_s (part / Sigma)); the whole grid gives all of them.
SampleCapture attributeOwnedCorners(const DensityGrid& grid, const CornerWeights& corners, double massShare,
                                    const Eigen::Vector3d& velocity,
                                    const Eigen::Vector3d& strip = Eigen::Vector3d::Zero());

// Eq. 9 for the segment from a to b with every sample attributed (P12), on a grid that
// owns every corner the samples read (serial runs; a block reads remote corners itself
// and calls attributeSample). collision is collisionMass(grid, ...)'s result to the bit.
SegmentCapture segmentCapture(const DensityGrid& grid, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                              double fiberRadius, const Eigen::Vector3d& segmentVelocity, double dt,
                              const CollisionOptions& options = CollisionOptions{});

// One parcel's reach into the nodes with depth (the nodes a block owns): the parts of its
// saturated share A_p and optical depth X_p, and its weights at those nodes. The parts are
// exact sums (FixedPointSum): added up over the blocks the parcel reached, they give the
// same A_p and X_p, to the bit, whatever the blocks (serial = parallel).
struct ParcelReach
{
    double saturated = 0.0;               // F_p sum w_pn over the saturated nodes
    double depth = 0.0;                   // F_p sum w_pn x_n over the others
    FixedPointSum saturatedSum, depthSum; // the same, exact (saturated, depth: their values)
    std::size_t first = 0, count = 0;     // its weights in ParcelReaches::weights
};

// The reaches of a step's parcels, in the order evaluated (reach() appends one each).
struct ParcelReaches
{
    std::vector<ParcelReach> parcels;
    std::vector<NodeWeight> weights; // F_p w_pn, per node with depth (CaptureLimit's places)
    void clear()
    {
        parcels.clear();
        weights.clear();
    }
};

class CaptureLimit
{
public:
    // Forgets the previous step.
    void clear();

    // --- 1. demand (any node; a block sends the foreign part to the owners) -----------------
    // shadow: each part's self-shadow sigma (P21, SelfShadow.hpp); interceptors: the
    // physical fibers the sample's fiber stands for (N, weighted fibers, docs/model.md
    // sec. 9), each asking the sample's part independently: the node's demand grows by N
    // times it and its depth by N times one fiber's (P40).
    void addDemand(const SampleCapture& sample, double interceptors = 1.0);
    void addDemand(const SegmentCapture& segment, double interceptors = 1.0);
    void addDemand(std::size_t node, double mass, double shadow = 0.0, double interceptors = 1.0);
    // Spread populations (docs/model.md sec. 12, SpreadPopulations.hpp) at an owned node:
    // their swept fraction P_n of the node's mass per step (demand s_n P_n, linear) and
    // their depth P'_n (added to x_n where s_n > 0). Added up over calls.
    void addSpread(std::size_t node, double share, double depth);
    // The demand at nodes the grid does not own, moved out, in node order: each addDemand
    // call's part apart (the owner multiplies their survivals, P13), in the order added.
    std::vector<NodeMass> takeForeignDemand(const DensityGrid& grid);

    // --- 2. optical depth, on the owner ----------------------------------------------------
    // x_n of every node with demand, from the window's mass per step. Throws
    // std::logic_error if demand at a node the grid does not own is left. The report's
    // massGranted is grant()'s.
    CaptureLimitReport limit(const DensityGrid& grid);
    // x_n (0 at nodes without demand or supply; infinity where saturated).
    double opticalDepth(std::size_t node) const;
    // The owned nodes with x_n > 0 (a block tells the others; empty: nothing to remove here).
    const IndexBox& takenBox() const { return takenBox_; }
    // True when the box (grid indices) may hold a node with x_n > 0: it meets a brick of
    // brickSize^3 nodes that holds one.
    bool mayTake(const IndexBox& box) const;
    static constexpr int brickSize = 4;

    // --- 3. removal ---------------------------------------------------------------------------
    // Appends the parcel's reach over the nodes this block owns (the whole grid: A_p and X_p
    // themselves). The same parcel and dt as deposited this step. A parcel whose deposit
    // nodes meet no brick with x_n > 0 costs a clip and a box, not its weights; the others'
    // weights are evaluated at the nodes with x_n > 0 only (DensityGrid::depositedShare).
    void reach(DensityGrid& grid, const Parcel& parcel, double dt, ParcelReaches& reaches) const;
    // c_p = 1 - (1 - A_p) exp(-X_p) from the whole A_p and X_p; 1 within 1e-12 of it.
    static double capturedFraction(double saturated, double depth);
    // (1 - A)(1 - e^-X): the part of c_p off the saturated nodes, accurate for small X
    static double capturedOffSaturated(double saturated, double depth);
    // The loss of parcel i of reaches (mass m_p, whole A_p and X_p) attributed to this
    // block's nodes: R_n += r_pn.
    void remove(const ParcelReaches& reaches, std::size_t i, double mass, double saturated, double depth);
    // --- 4. grant ------------------------------------------------------------------------------
    // g_n = R_n / d_n at every node with demand (1 where d_n = 0); report.massGranted = sum R_n.
    void grant(CaptureLimitReport& report);
    // g_n of a node with demand (grant() on its owner); throws std::out_of_range for a node
    // without one.
    double grantedRatio(std::size_t node) const;
    // s_n g_n, the granted mass per unit of swept fraction (a spread population's grant,
    // SpreadPopulations.hpp, P51), dense over `region` (grid indices, flatIndexInBox order;
    // 0 where no demand), times the node's unremovedShare where `unremoved` (P33).
    void grantedSupplies(const IndexBox& region, bool unremoved, std::vector<double>& values) const;
    // The sample's mass after the limit: sum_c d_sc g_{n_c}; momentum = that * velocity.
    double grantedMass(const SampleCapture& sample) const;
    // The segment's mass and momentum after the limit.
    SegmentCollision granted(const SegmentCapture& segment) const;

    // Serial runs (one grid owning every node): reach, c_p, remove for every parcel, then
    // grant; returns c_p per parcel. The reaches kept in *kept if given (discrete hits,
    // RealisedCapture.hpp).
    std::vector<double> removeFromParcels(DensityGrid& grid, const std::vector<Parcel>& parcels, double dt,
                                          CaptureLimitReport& report, ParcelReaches* kept = nullptr);

    // --- discrete hits: a per-node factor on the removal -----------------------------------
    // The fibers realised q times the granted R_n at an owned node (after grant()).
    void scaleRemoval(std::size_t node, double q);
    // sum_n r_pn q_n / m_p over this block's nodes for parcel i (whole A_p and X_p): the
    // parts add up over the blocks to the fraction parcel p must lose (c_p where every q_n = 1).
    double removedFraction(const ParcelReaches& reaches, std::size_t i, double saturated, double depth) const;
    // The same as an exact sum (FixedPointSum; each term at most 2: the fraction is clamped
    // to 1 anyway), whose parts add up over the blocks to the bit.
    FixedPointSum removedFractionSum(const ParcelReaches& reaches, std::size_t i, double saturated,
                                     double depth) const;
    // Parcel i (whole A_p and X_p) gives less than its parts ask (P33): shortfall_n +=
    // unremoved r_pn q_n / m_p at its nodes here, unremoved = m_p (1 - 1 / x_p) (kg),
    // x_p = summedParts (removedFractionSum's value over all blocks; its clamped terms
    // accounted for).
    void addShortfall(const ParcelReaches& reaches, std::size_t i, double saturated, double depth,
                      double unremoved, double summedParts);
    // shortfall_n / (q_n R_n): the part of node n's realised mass its parcels did not give
    // (0 where none fell short; in [0, 1]).
    double unremovedShare(std::size_t node) const;

private:
    // The largest term r_pn q_n / m_p removedFractionSum adds (a parcel asked more at one
    // node gives all it has whatever the others): the exact sum's range bounded.
    static constexpr double largestRemovalTerm = 2.0;
    // r_pn / m_p at each of parcel i's nodes here, in the order reached: f(place, share).
    template <class F>
    void forEachRemovalShare(const ParcelReaches& reaches, std::size_t i, double saturated, double depth,
                             F&& f) const;
    // False when the parcel's deposit cannot reach a node with x_n > 0 (a cheap bound from
    // r_max, checked before its weights are evaluated).
    bool mayReach(const GridSpec& spec, const KernelSettings& kernel, const Parcel& parcel, double dt) const;
    // entry's exact A_p and X_p parts (and their values) from its weights.
    void sumReach(const std::vector<NodeWeight>& weights, ParcelReach& entry) const;
    // Clears takenBrick_ (the bricks set only).
    void forgetTakenBricks();
    // x_n > 0 at the node: takenBox_ and its brick.
    void markTaken(std::size_t node, const std::array<int, 3>& nodes);
    std::size_t brickIndex(int i, int j, int k) const
    {
        return static_cast<std::size_t>(i)
            + bricks_[0] * (static_cast<std::size_t>(j) + bricks_[1] * static_cast<std::size_t>(k));
    }

    // One interceptor's part of a node's demand: d_sn, its self-shadow sigma (P21) and the
    // physical fibers asking it (P40)
    struct DemandPart
    {
        double mass = 0.0, shadow = 0.0, interceptors = 1.0;
        bool operator<(const DemandPart& other) const
        {
            if (mass != other.mass)
                return mass < other.mass;
            if (shadow != other.shadow)
                return shadow < other.shadow;
            return interceptors < other.interceptors;
        }
    };
    // Per node: the demand d_n and its parts d_sn, one per interceptor (addDemand call)
    struct NodeDemand
    {
        double total = 0.0;
        std::vector<DemandPart> parts;
        double spreadShare = 0.0, spreadDepth = 0.0; // P_n, P'_n (addSpread)
        double supply = 0.0;                         // s_n, set by limit()
    };
    // The parts in value order and their total (the same bits whatever the order added).
    static void sortParts(NodeDemand& entry);
    // removed_ from removedTerms_ (remove()'s r_pn), summed per node in value order.
    void sumRemovedTerms();
    // x_n = sum of the parts' depths, N a (1 + sigma) to second order (P13, P21, P40);
    // infinity where a part is >= s_n
    static double depthOf(const std::vector<DemandPart>& parts, double supply);
    std::unordered_map<std::size_t, NodeDemand> demand_;
    std::unordered_map<std::size_t, double> granted_; // g_n
    std::unordered_map<std::size_t, double> depth_;   // x_n > 0, owned nodes
    // depth_ in node order with grid indices (the parcels' sums; value x_n, 0 where
    // saturated), built by limit(); per place the removed mass R_n, whether saturated, and
    // the removal's factor q_n. 40 + 25 bytes per node with x_n > 0.
    SparseNodeValues depthNodes_;
    std::vector<double> removed_;
    std::vector<std::pair<std::uint32_t, double>> removedTerms_; // (place, r_pn), until grant()
    std::vector<unsigned char> saturated_;
    std::vector<double> removalScale_;
    std::vector<double> shortfall_;
    std::array<int, 3> gridNodes_{}; // the grid's nodes per direction
    IndexBox takenBox_;
    std::array<std::size_t, 3> bricks_{};     // per direction, over the grid
    std::vector<unsigned char> takenBrick_;   // per brick of the grid: 1 when it holds x_n > 0
    std::vector<std::size_t> takenBrickList_; // the bricks set, to clear them
};

} // namespace dropletFiber
