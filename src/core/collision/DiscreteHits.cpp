#include "collision/DiscreteHits.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dropletFiber
{

namespace
{
constexpr std::uint32_t hitStream = 0x80000000u;
constexpr std::uint32_t blockBits = 11;
constexpr std::uint32_t sampleLimit = 1u << 20;
} // namespace

HitUniforms::HitUniforms(const HitKey& key)
{
    if ((key.fiberId >> 32) != 0 || key.sample >= sampleLimit)
    {
        throw std::invalid_argument("HitUniforms: fiber id " + std::to_string(key.fiberId)
                                    + " must be < 2^32 and sample " + std::to_string(key.sample) + " < 2^20");
    }
    counter_
        = {key.segment, std::uint32_t(key.step), std::uint32_t(key.step >> 32), std::uint32_t(key.fiberId)};
    key_ = {key.seed, hitStream | (key.sample << blockBits)};
}

double HitUniforms::next()
{
    if (used_ == 4)
    {
        if (block_ >= (1u << blockBits))
        {
            throw std::runtime_error("HitUniforms: more than 2048 Philox blocks for one key");
        }
        PhiloxKey key = key_;
        key[1] |= block_++;
        bits_ = philox4x32_10(counter_, key);
        used_ = 0;
    }
    return uniformOpen(bits_[static_cast<std::size_t>(used_++)]);
}

double hitMass(const DropletFieldValue& field, double fiberRadius, RadiusAverage radiusAverage)
{
    if (!field.inside || !(field.rho > 0.0) || !(field.numberDensity > 0.0))
    {
        return 0.0;
    }
    // Expected hits 2 n (r_F + <r>_number) |l x v| dt, expected mass 2 rho (r_F + <r>) |l x v| dt
    const double radius = radiusAverage == RadiusAverage::Mass ? field.rMeanMass : field.rMeanNumber;
    return field.rho / field.numberDensity * (fiberRadius + radius) / (fiberRadius + field.rMeanNumber);
}

SampleHits sampleHits(CollisionMode mode, double grantedMass, double dropletMass, const HitKey& key)
{
    SampleHits hits;
    if (!(grantedMass > 0.0) || !(dropletMass > 0.0))
    {
        return hits;
    }
    const double lambda = grantedMass / dropletMass;
    if (mode == CollisionMode::Expected)
    {
        hits.count = lambda;
        hits.mass = grantedMass;
        return hits;
    }
    HitUniforms uniforms(key);
    hits.count = poissonCount(lambda, uniforms);
    hits.mass = hits.count * dropletMass;
    return hits;
}

} // namespace dropletFiber
