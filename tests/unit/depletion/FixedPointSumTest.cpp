// FixedPointSum (src/core/depletion/FixedPointSum.hpp): the exact sum behind serial =
// parallel to the bit. Its value is the correctly rounded sum of the terms (each rounded
// to the quantum 2^-104) whatever their order and grouping into parts: checked against
// sums known exactly by hand and in integers, against a long double sum, and under
// shuffles and random splits into parts (the blocks of a parcel's deposit).
#include "depletion/FixedPointSum.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <vector>

using namespace dropletFiber;

namespace
{

double sumOf(const std::vector<double>& terms)
{
    FixedPointSum sum;
    for (const double x : terms)
    {
        sum.add(x);
    }
    return sum.value();
}

// Terms like a parcel's depth parts: magnitudes 1e-20 to 1e2, a few negative
std::vector<double> mixedTerms(std::mt19937_64& random, int n)
{
    std::uniform_real_distribution<double> exponent(-20.0, 2.0), unit(0.0, 1.0);
    std::vector<double> terms(static_cast<std::size_t>(n));
    for (double& x : terms)
    {
        x = std::pow(10.0, exponent(random)) * (unit(random) < 0.1 ? -1.0 : 1.0);
    }
    return terms;
}

} // namespace

TEST(FixedPointSum, TenTimesTheDoubleNearestOneTenthIsOne)
{
    // 0.1 is 3602879701896397 2^-55; ten of them 36028797018963970 2^-55, which to 53 bits
    // is 9007199254740992.5 2^-53: a tie, rounded to the even 2^53 2^-53 = 1 exactly. The
    // sum in doubles, left to right, gives 1 - 2^-53 (one below)
    EXPECT_EQ(sumOf(std::vector<double>(10, 0.1)), 1.0);
    double naive = 0.0;
    for (int i = 0; i < 10; ++i)
    {
        naive += 0.1;
    }
    EXPECT_NE(naive, 1.0);
}

TEST(FixedPointSum, WholeMultiplesOfAPowerOfTwoSumAsTheirIntegers)
{
    // x_i = a_i 2^-60 with a_i < 2^53: the exact sum is (sum a_i) 2^-60, the integer sum
    // in 64 bits; its double is the integer's correctly rounded conversion
    std::mt19937_64 random(7);
    std::uniform_int_distribution<std::int64_t> digits(0, (std::int64_t(1) << 53) - 1);
    for (int trial = 0; trial < 50; ++trial)
    {
        std::int64_t whole = 0;
        std::vector<double> terms;
        for (int i = 0; i < 200; ++i)
        {
            const std::int64_t a = digits(random);
            whole += a;
            terms.push_back(std::ldexp(static_cast<double>(a), -60));
        }
        EXPECT_EQ(sumOf(terms), std::ldexp(static_cast<double>(whole), -60));
    }
}

TEST(FixedPointSum, AgreesWithALongDoubleSum)
{
    // long double (64-bit mantissa) sums 1000 terms of at most 1e2 within 1000 * 2^-64 * 1e5;
    // the exact sum is within half a quantum per term of the terms' sum
    std::mt19937_64 random(11);
    for (int trial = 0; trial < 20; ++trial)
    {
        const std::vector<double> terms = mixedTerms(random, 1000);
        long double reference = 0.0L, magnitude = 0.0L;
        for (const double x : terms)
        {
            reference += x;
            magnitude += std::fabs(x);
        }
        const double bound = 1000.0 * std::ldexp(static_cast<double>(magnitude), -63)
            + 1000.0 * std::ldexp(1.0, -104) + std::fabs(static_cast<double>(reference)) * 0x1p-53;
        EXPECT_NEAR(sumOf(terms), static_cast<double>(reference), bound);
    }
}

TEST(FixedPointSum, AnyOrderAndGroupingGivesTheSameBits)
{
    std::mt19937_64 random(13);
    for (int trial = 0; trial < 20; ++trial)
    {
        std::vector<double> terms = mixedTerms(random, 300);
        FixedPointSum whole;
        for (const double x : terms)
        {
            whole.add(x);
        }
        bool naiveDiffered = false;
        double firstNaive = 0.0;
        for (int shuffle = 0; shuffle < 10; ++shuffle)
        {
            std::shuffle(terms.begin(), terms.end(), random);
            // Split into 1 to 5 parts (blocks), each sent as its pieces and added up
            const int parts = 1 + shuffle % 5;
            std::vector<FixedPointSum> part(static_cast<std::size_t>(parts));
            double naive = 0.0;
            for (std::size_t i = 0; i < terms.size(); ++i)
            {
                part[i % part.size()].add(terms[i]);
                naive += terms[i];
            }
            FixedPointSum total;
            for (const FixedPointSum& p : part)
            {
                const auto pieces = p.pieces();
                total.add(FixedPointSum::fromPieces(pieces.data()));
            }
            EXPECT_TRUE(total == whole);
            EXPECT_EQ(total.value(), whole.value());
            firstNaive = shuffle == 0 ? naive : firstNaive;
            naiveDiffered = naiveDiffered || naive != firstNaive;
        }
        // The terms are such that the double sum does depend on the order
        EXPECT_TRUE(naiveDiffered || trial > 0);
    }
}

TEST(FixedPointSum, TermsRoundToTheQuantum)
{
    const double quantum = std::ldexp(1.0, -FixedPointSum::fractionBits);
    FixedPointSum half;
    half.add(0.5 * quantum); // a half: away from zero
    EXPECT_EQ(half.value(), quantum);
    FixedPointSum below;
    below.add(0.49 * quantum);
    EXPECT_EQ(below.value(), 0.0);
    FixedPointSum negative;
    negative.add(-1.5 * quantum);
    EXPECT_EQ(negative.value(), -2.0 * quantum);
    // A sum >= 2^-52 keeps every bit: its ulp is a whole number of quanta
    FixedPointSum fine;
    fine.add(std::ldexp(1.0, -52) + std::ldexp(1.0, -104));
    EXPECT_EQ(fine.value(), std::ldexp(1.0, -52) + std::ldexp(1.0, -104));
}

TEST(FixedPointSum, NegativeSumsTravelAsPieces)
{
    FixedPointSum sum;
    sum.add(-123.456);
    sum.add(1e-20);
    const auto pieces = sum.pieces();
    for (const double piece : pieces)
    {
        EXPECT_GE(piece, 0.0);
        EXPECT_LT(piece, std::ldexp(1.0, 43));
    }
    EXPECT_TRUE(FixedPointSum::fromPieces(pieces.data()) == sum);
    EXPECT_EQ(FixedPointSum::fromPieces(pieces.data()).value(), -123.456 + 1e-20);
}

TEST(FixedPointSum, BeyondTheRangeThrows)
{
    FixedPointSum sum;
    EXPECT_THROW(sum.add(5e6), std::overflow_error);
    FixedPointSum near;
    near.add(4e6);
    EXPECT_THROW(near.add(4e6), std::overflow_error);
    EXPECT_THROW(near.add(std::nan("")), std::overflow_error);
    const double notWhole[3] = {0.5, 0.0, 0.0};
    EXPECT_THROW(FixedPointSum::fromPieces(notWhole), std::invalid_argument);
}
