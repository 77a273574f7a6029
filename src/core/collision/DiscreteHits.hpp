// DiscreteHits: the whole number of droplets a collision sample catches in a step
// (collision mode discrete, docs/model.md sec. 3, P30-P32). Droplets placed independently
// in space are hit independently: the count is Poisson with the expected count of eq. 9
// as its mean,
//     lambda = m_granted / m_hit,  m_hit = (rho / n) (r_F + <r>) / (r_F + <r>_number)   (P30)
// (<r> the radius average eq. 9 used; the grid's moments give rho, n, <r>_number and
// <r>_mass: for a monodisperse spray m_hit is the droplet's mass). The sample receives
// N m_hit and N m_hit u_droplet. The law is not truncated: with depletion the parcels
// lose what was realised (RealisedCapture.hpp, P31-P32).
//
// Random numbers: Philox4x32-10 (CounterRandom) keyed by (seed, fiber id, segment, sample,
// step): counter (segment, low and high word of step, low word of fiber id), key (seed,
// stream bit | sample << 11 | block). The stream bit (bit 31 of the key's second word) is
// clear for the turbulent air's keys (the high word of a fiber id below 2^63), so hits and
// turbulence never share a draw; fiber ids must be below 2^32 here.
#pragma once

#include "collision/CollisionMass.hpp"
#include "collision/PoissonSampler.hpp"
#include "fiber/CounterRandom.hpp"

#include <cstdint>

namespace dropletFiber
{

// What identifies one sample's draw.
struct HitKey
{
    std::uint32_t seed = 0;
    std::uint64_t fiberId = 0;
    std::uint32_t segment = 0;
    std::uint32_t sample = 0; // of the segment's samples, < 2^20
    std::uint64_t step = 0;   // time index
};

// The uniforms of one key: four per Philox block, blocks 0, 1, ... (at most 2048).
class HitUniforms : public UniformSource
{
public:
    explicit HitUniforms(const HitKey& key);
    double next() override;

private:
    PhiloxCounter counter_{};
    PhiloxKey key_{};
    std::uint32_t block_ = 0;
    PhiloxCounter bits_{};
    int used_ = 4;
};

// m_hit of P30: the mean mass of a caught droplet at the sample, kg (0 without droplets).
double hitMass(const DropletFieldValue& field, double fiberRadius, RadiusAverage radiusAverage);

struct SampleHits
{
    double count = 0.0; // droplets caught (expected mode: the expected count lambda)
    double mass = 0.0;  // kg
};

// The sample's hits in the mode's way: expected, lambda and the granted mass; discrete,
// N ~ Poisson(lambda) and N m_hit.
SampleHits sampleHits(CollisionMode mode, double grantedMass, double dropletMass, const HitKey& key);

} // namespace dropletFiber
