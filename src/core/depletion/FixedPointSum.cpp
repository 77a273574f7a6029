#include "depletion/FixedPointSum.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

namespace dropletFiber
{

namespace
{
using Unsigned = unsigned __int128;

// The largest magnitude in quanta: 2^(22 + 104) = 2^126, with room for a sum of two
constexpr int rangeBits = 126;
constexpr int pieceBits = 43;

[[noreturn]] void outOfRange(double x)
{
    throw std::overflow_error("FixedPointSum: " + std::to_string(x)
                              + " is beyond the exact sum's range (magnitude below 2^22, ~4.2e6)");
}
} // namespace

void FixedPointSum::add(double x)
{
    if (x == 0.0)
    {
        return;
    }
    if (!std::isfinite(x))
    {
        outOfRange(x);
    }
    std::uint64_t bits = 0;
    std::memcpy(&bits, &x, sizeof bits);
    const int biased = static_cast<int>((bits >> 52) & 0x7ff);
    std::uint64_t mantissa = bits & ((std::uint64_t(1) << 52) - 1);
    // x = mantissa 2^(exponent), mantissa an integer (subnormals: no hidden bit)
    int exponent = biased - 1075;
    if (biased != 0)
    {
        mantissa |= std::uint64_t(1) << 52;
    }
    else
    {
        exponent = -1074;
    }
    const int shift = exponent + fractionBits; // x in quanta = mantissa 2^shift
    Unsigned magnitude = 0;
    if (shift >= 0)
    {
        if (shift + 53 > rangeBits)
        {
            outOfRange(x);
        }
        magnitude = Unsigned(mantissa) << shift;
    }
    else if (shift > -54)
    {
        // Rounded to the nearest quantum, halves away from zero: the same for every x
        magnitude = (Unsigned(mantissa) + (Unsigned(1) << (-shift - 1))) >> -shift;
    }
    const __int128 term = static_cast<__int128>(magnitude);
    units_ += (bits >> 63) != 0 ? -term : term;
    const __int128 limit = static_cast<__int128>(Unsigned(1) << rangeBits);
    if (units_ >= limit || units_ <= -limit)
    {
        outOfRange(value());
    }
}

void FixedPointSum::add(const FixedPointSum& other)
{
    units_ += other.units_;
    const __int128 limit = static_cast<__int128>(Unsigned(1) << rangeBits);
    if (units_ >= limit || units_ <= -limit)
    {
        outOfRange(value());
    }
}

double FixedPointSum::value() const
{
    // The magnitude's top 64 bits, with a sticky bit for the rest, converted once: the
    // conversion rounds to nearest (ties to even) as the exact value would be rounded
    const bool negative = units_ < 0;
    Unsigned magnitude = negative ? Unsigned(-units_) : Unsigned(units_);
    int dropped = 0;
    if ((magnitude >> 64) != 0)
    {
        // Down to exactly 64 bits, the bits shifted out kept as a sticky last bit
        const auto high = static_cast<std::uint64_t>(magnitude >> 64);
        dropped = 64 - __builtin_clzll(high);
        const bool sticky = (magnitude & ((Unsigned(1) << dropped) - 1)) != 0;
        magnitude = (magnitude >> dropped) | Unsigned(sticky ? 1 : 0);
    }
    // 64 bits rounded to 53 with the sticky bit: exact round-to-nearest of the whole
    const double rounded
        = std::ldexp(static_cast<double>(static_cast<std::uint64_t>(magnitude)), dropped - fractionBits);
    return negative ? -rounded : rounded;
}

std::array<double, FixedPointSum::pieceCount> FixedPointSum::pieces() const
{
    const Unsigned bits = static_cast<Unsigned>(units_);
    const Unsigned mask = (Unsigned(1) << pieceBits) - 1;
    std::array<double, pieceCount> out{};
    for (int i = 0; i < pieceCount; ++i)
    {
        out[static_cast<std::size_t>(i)]
            = static_cast<double>(static_cast<std::uint64_t>((bits >> (pieceBits * i)) & mask));
    }
    return out;
}

FixedPointSum FixedPointSum::fromPieces(const double* pieces)
{
    Unsigned bits = 0;
    for (int i = 0; i < pieceCount; ++i)
    {
        const double piece = pieces[i];
        if (!(piece >= 0.0 && piece < std::ldexp(1.0, pieceBits) && piece == std::floor(piece)))
        {
            throw std::invalid_argument(
                "FixedPointSum::fromPieces: a piece is not a whole number below 2^43");
        }
        bits |= Unsigned(static_cast<std::uint64_t>(piece)) << (pieceBits * i);
    }
    FixedPointSum sum;
    sum.units_ = static_cast<__int128>(bits);
    return sum;
}

} // namespace dropletFiber
