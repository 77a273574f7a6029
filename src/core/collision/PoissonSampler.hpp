// PoissonSampler: a Poisson-distributed count from a stream of uniforms, for the discrete
// hits of docs/model.md sec. 3 (collision mode discrete). Both branches are exact (no
// approximation of the law):
//   lambda < 10   inversion by sequential search (chop-down): P(0) = exp(-lambda),
//                 P(k) = P(k-1) lambda / k, one uniform per draw;
//   lambda >= 10  PTRS, the transformed rejection with squeeze of Hoermann ("The
//                 transformed rejection method for generating Poisson random
//                 variables", Insurance: Mathematics and Economics 12, 1993): two
//                 uniforms per attempt, accepted with probability > 0.85 per attempt.
// The uniforms are (bits + 1/2) / 2^32 (CounterRandom::uniformOpen): the inversion
// resolves probabilities down to 2^-32, far below what any test or case here can see.
#pragma once

#include <cstdint>

namespace dropletFiber
{

// Where the sampler takes its uniforms on (0, 1) from.
class UniformSource
{
public:
    virtual ~UniformSource() = default;
    virtual double next() = 0;
};

// Below this mean the inversion, from it on PTRS.
constexpr double poissonInversionLimit = 10.0;

// A Poisson(lambda) count, lambda >= 0 and finite (std::invalid_argument otherwise).
double poissonCount(double lambda, UniformSource& uniforms);

} // namespace dropletFiber
