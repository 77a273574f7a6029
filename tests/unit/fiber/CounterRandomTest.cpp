// CounterRandom: Philox4x32-10 against the published known-answer vectors, and the
// Gaussians it gives: mean, variance, fourth moment and independence of neighbouring
// keys, within statistical tolerances stated below.
#include "fiber/CounterRandom.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace dropletFiber;

// Random123 tests/kat_vectors, the three "philox4x32 10" lines (counter[4] key[2] ->
// output[4]); Salmon et al., SC'11.
TEST(CounterRandom, PhiloxKnownAnswers)
{
    EXPECT_EQ(philox4x32_10({0, 0, 0, 0}, {0, 0}),
              (PhiloxCounter{0x6627e8d5u, 0xe169c58du, 0xbc57ac4cu, 0x9b00dbd8u}));
    const std::uint32_t ones = 0xffffffffu;
    EXPECT_EQ(philox4x32_10({ones, ones, ones, ones}, {ones, ones}),
              (PhiloxCounter{0x408f276du, 0x41c83b0eu, 0xa20bc7c6u, 0x6d5451fdu}));
    EXPECT_EQ(philox4x32_10({0x243f6a88u, 0x85a308d3u, 0x13198a2eu, 0x03707344u}, {0xa4093822u, 0x299f31d0u}),
              (PhiloxCounter{0xd16cfe09u, 0x94fdccebu, 0x5001e420u, 0x24126ea1u}));
}

TEST(CounterRandom, UniformIsOpen)
{
    EXPECT_GT(uniformOpen(0u), 0.0);
    EXPECT_LT(uniformOpen(0xffffffffu), 1.0);
    EXPECT_DOUBLE_EQ(uniformOpen(0x80000000u), 0.5 + 0.5 * 0x1p-32);
}

// N = 4 x 100000 normals: standard errors of the mean 1/sqrt(N) = 0.0016, of the
// variance sqrt(2/N) = 0.0022, of the fourth moment sqrt(96/N) = 0.015; of the
// correlation of neighbouring points' draws 1/sqrt(N/4) = 0.0032. Tolerances 5 of them.
TEST(CounterRandom, GaussianMoments)
{
    const int draws = 100000;
    double sum = 0, sum2 = 0, sum4 = 0, cross = 0;
    for (int d = 0; d < draws; ++d)
    {
        const auto g = fiberPointGaussians(7u, 12345u, std::uint32_t(d % 50), std::uint64_t(d / 50));
        const auto next = fiberPointGaussians(7u, 12345u, std::uint32_t(d % 50) + 1u, std::uint64_t(d / 50));
        for (const double x : g)
        {
            sum += x;
            sum2 += x * x;
            sum4 += x * x * x * x;
        }
        cross += g[0] * next[0];
    }
    const double n = 4.0 * draws;
    EXPECT_NEAR(sum / n, 0.0, 5 * 0.0016);
    EXPECT_NEAR(sum2 / n, 1.0, 5 * 0.0022);
    EXPECT_NEAR(sum4 / n, 3.0, 5 * 0.015);
    EXPECT_NEAR(cross / draws, 0.0, 5 * 0.0032);
}

// Each part of the key changes the draw (fiber ids beyond 32 bits included).
TEST(CounterRandom, EveryKeyPartCounts)
{
    const auto base = fiberPointGaussians(1u, 5u, 2u, 3u);
    EXPECT_NE(base, fiberPointGaussians(2u, 5u, 2u, 3u));
    EXPECT_NE(base, fiberPointGaussians(1u, 6u, 2u, 3u));
    EXPECT_NE(base, fiberPointGaussians(1u, 5u + (std::uint64_t(1) << 32), 2u, 3u));
    EXPECT_NE(base, fiberPointGaussians(1u, 5u, 3u, 3u));
    EXPECT_NE(base, fiberPointGaussians(1u, 5u, 2u, 4u));
    EXPECT_NE(base, fiberPointGaussians(1u, 5u, 2u, 3u + (std::uint64_t(1) << 32)));
    EXPECT_EQ(base, fiberPointGaussians(1u, 5u, 2u, 3u));
}
