// KeptTables: the separable tables (SeparableWeight) the step's deposit built for the
// parcels near the fibers, kept for the removal of the same step (docs/model.md sec. 7,
// DensityGrid::depositedShare), which re-weighs those parcels at the nodes the fibers took
// from: it reads the kept tables instead of rebuilding them (the axis tables' exponentials
// and the normalising sum were ~60 % of the removal's time in the spray3D case).
//
// Which parcels: those whose (folded) weighted box meets a region of nodes the caller
// names before the deposit (setRegion; the OpenFOAM layer: the nodes of the cells the
// fibers lie in, which do not move between the deposit and the collision). The region
// decides only what is kept, never a result: a parcel found here gets the very tables its
// rebuild would give (the key below fixes every input of them on the same grid), and a
// parcel not found is rebuilt as before. An empty region (the default) keeps nothing.
//
// Key: the clipped path (start, displacement), the diameter and nParticle, bit for bit:
// with the grid's spec and kernel settings they fix the kernel, the box, the points Q and
// the tables. Found by a hash and compared in full.
//
// Memory: per kept parcel Q (1 + nx + ny + nz) doubles (W_q and the three (folded) axis
// tables) plus 152 bytes of entry and index. spray3D (docs/performance.md, the removal;
// bytes() and parcels() after each step's removal, 400 steps): 2.3 kB per kept parcel on
// average, 123 of ~136 separable parcels a step kept (the fibers' cells span most of the
// spray there), 0.29 MB a step on average, 0.37 MB at most; ~78 of them re-weighed. The
// vectors are cleared, not freed, per step: their capacity is the largest step's.
#pragma once

#include "grid/GridSpec.hpp"
#include "grid/SeparableWeight.hpp"

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace dropletFiber
{

class KeptTables
{
public:
    // The inputs that fix a parcel's tables (bitwise).
    struct Key
    {
        std::array<double, 8> values{}; // path start, displacement, diameter, nParticle

        Key() = default;
        Key(const Eigen::Vector3d& start, const Eigen::Vector3d& displacement, double diameter,
            double nParticle);
        bool operator==(const Key& other) const;
        std::uint64_t hash() const;
    };
    // One parcel's kept tables.
    struct Entry
    {
        Key key;
        IndexBox box;          // the (folded) weighted box the tables cover
        double omegaSum = 0.0; // SeparableWeight::sum()
        int points = 0;        // Q
        bool lanes = false;    // SeparableWeight::vectorised()
        std::array<std::size_t, 3> length{};
        std::size_t offset = 0; // first of its values in values_
    };

    // The region whose parcels the next steps' deposits keep (grid indices; empty: none).
    void setRegion(const IndexBox& region) { region_ = region; }
    const IndexBox& region() const { return region_; }
    // True when a parcel with this weighted box is to be kept.
    bool keeps(const IndexBox& weightedBox) const { return !weightedBox.intersected(region_).empty(); }
    // Keeps the tables the separable weights hold now.
    void keep(const Key& key, const SeparableWeight& weights, double omegaSum, const IndexBox& box);
    // The entry of the key, or nullptr.
    const Entry* find(const Key& key) const;
    // The entry's tables (valid until the next keep() or clear()).
    SeparableTables tables(const Entry& entry) const;
    // Forgets the entries, keeping the memory.
    void clear();

    // The parcels kept, the lookups that found theirs since, and the bytes they take
    // (tables, entries and index).
    std::size_t parcels() const { return entries_.size(); }
    std::size_t found() const { return found_; }
    std::size_t bytes() const;

private:
    IndexBox region_;
    std::vector<Entry> entries_;
    std::vector<double> values_;
    // (hash, entry) sorted by hash, built at the first find() after a keep().
    mutable std::vector<std::pair<std::uint64_t, std::size_t>> index_;
    mutable bool indexed_ = true;
    mutable std::size_t found_ = 0;
};

} // namespace dropletFiber
