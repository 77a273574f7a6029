#include "fiber/CounterRandom.hpp"

#include <cmath>

namespace dropletFiber
{

namespace
{
// Philox 4x32 multipliers and Weyl key increments (Salmon et al. 2011, table 2;
// Random123 PHILOX_M4x32_0/1, PHILOX_W32_0/1).
constexpr std::uint32_t multiplier0 = 0xD2511F53u;
constexpr std::uint32_t multiplier1 = 0xCD9E8D57u;
constexpr std::uint32_t weyl0 = 0x9E3779B9u;
constexpr std::uint32_t weyl1 = 0xBB67AE85u;

PhiloxCounter philoxRound(const PhiloxCounter& c, const PhiloxKey& k)
{
    const std::uint64_t product0 = std::uint64_t(multiplier0) * c[0];
    const std::uint64_t product1 = std::uint64_t(multiplier1) * c[2];
    const auto hi0 = std::uint32_t(product0 >> 32), lo0 = std::uint32_t(product0);
    const auto hi1 = std::uint32_t(product1 >> 32), lo1 = std::uint32_t(product1);
    return {hi1 ^ c[1] ^ k[0], lo1, hi0 ^ c[3] ^ k[1], lo0};
}

} // namespace

PhiloxCounter philox4x32_10(PhiloxCounter counter, PhiloxKey key)
{
    counter = philoxRound(counter, key);
    for (int round = 1; round < 10; ++round)
    {
        key[0] += weyl0; // unsigned: wraps modulo 2^32 as the algorithm requires
        key[1] += weyl1;
        counter = philoxRound(counter, key);
    }
    return counter;
}

double uniformOpen(std::uint32_t bits)
{
    return (double(bits) + 0.5) * 0x1p-32;
}

std::array<double, 4> gaussianQuadruple(const PhiloxCounter& counter, const PhiloxKey& key)
{
    const PhiloxCounter bits = philox4x32_10(counter, key);
    std::array<double, 4> normals{};
    for (int pair = 0; pair < 2; ++pair)
    {
        const double radius = std::sqrt(-2.0 * std::log(uniformOpen(bits[2 * pair])));
        const double angle = 2.0 * M_PI * uniformOpen(bits[2 * pair + 1]);
        normals[2 * pair] = radius * std::cos(angle);
        normals[2 * pair + 1] = radius * std::sin(angle);
    }
    return normals;
}

std::array<double, 4> fiberPointGaussians(std::uint32_t seed, std::uint64_t fiberId, std::uint32_t point,
                                          std::uint64_t step)
{
    const PhiloxCounter counter{point, std::uint32_t(step), std::uint32_t(step >> 32),
                                std::uint32_t(fiberId)};
    const PhiloxKey key{seed, std::uint32_t(fiberId >> 32)};
    return gaussianQuadruple(counter, key);
}

} // namespace dropletFiber
