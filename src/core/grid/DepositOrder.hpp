// DepositOrder: the order in which a block deposits its parcels and the copies it received,
// the same on every decomposition (docs/model.md sec. 4, grid blocks). A node's step value
// is a floating-point sum over the parcels that reach it; a parallel block meets its own
// parcels and the copies of other processors' parcels, a serial run all parcels in the
// cloud's order. Deposited in the order of a key taken from the parcel's content (its nine
// numbers, compared as bit patterns: a total order, NaN included), every node receives its
// terms in the same order on every run, so the sums are the same bits (each parcel's weight
// at a node does not depend on which block evaluates it). Equal keys are equal parcels,
// whose terms are equal: their order does not matter.
#pragma once

#include "grid/Parcel.hpp"

#include <cstddef>
#include <vector>

namespace dropletFiber
{

// One parcel to deposit: own (index into the processor's parcels) or a copy received.
struct DepositEntry
{
    bool copy = false;
    std::size_t index = 0;
};

// True when a's key orders before b's.
bool depositsBefore(const Parcel& a, const Parcel& b);

// The own parcels and the copies, merged in key order.
std::vector<DepositEntry> depositOrder(const std::vector<Parcel>& own, const std::vector<Parcel>& copies);

} // namespace dropletFiber
