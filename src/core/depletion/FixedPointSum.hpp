// FixedPointSum: an exact, order-independent sum of doubles, for the sums whose terms are
// split over grid blocks (a parcel's optical depth X_p, saturated share A_p and realised
// removal over the nodes its deposit reached, docs/model.md sec. 4 and 7). Each term is
// rounded once to a multiple of the quantum 2^-104 (~4.9e-32) and added as an integer
// (__int128), so any grouping of the terms (one block, or parts from several blocks added
// up on the parcel's processor) gives the same integer, and value() the same double:
// serial = parallel to the bit, for any partition of the grid into blocks.
// Precision: a term's absolute error is at most half a quantum; a sum >= 2^-52 (~2.2e-16)
// keeps every bit of a double (its ulp is at least a quantum). Range: |sum| < 2^22
// (~4.2e6); beyond it add() throws std::overflow_error (the dimensionless depths and
// fractions summed here are below ~1e3).
// Transport: exact, as three doubles (43-bit pieces of the integer), for the exchanges.
#pragma once

#include <array>

namespace dropletFiber
{

class FixedPointSum
{
public:
    // Bits after the binary point: the quantum is 2^-fractionBits.
    static constexpr int fractionBits = 104;
    // The number of doubles pieces() gives and fromPieces() takes.
    static constexpr int pieceCount = 3;

    // Adds x rounded to the nearest multiple of the quantum (ties away from zero).
    void add(double x);
    void add(const FixedPointSum& other);
    // The sum rounded to the nearest double (ties to even): the same for any order.
    double value() const;
    bool operator==(const FixedPointSum& other) const { return units_ == other.units_; }

    // The integer as three doubles, each a whole number below 2^43 (exact), and back.
    std::array<double, pieceCount> pieces() const;
    static FixedPointSum fromPieces(const double* pieces);

private:
    __int128 units_ = 0; // the sum in quanta
};

} // namespace dropletFiber
