// Seeded randomness that gives the same numbers on every machine and standard library.
//
// std::uniform_real_distribution and friends are implementation-defined, so runs would differ
// between compilers; this wraps the fully specified std::mt19937_64 engine and derives every
// distribution from its raw 64-bit output.
#pragma once

#include <cstdint>
#include <random>

namespace coinspect {

class Rng {
 public:
  explicit Rng(uint64_t seed) : engine_(seed) {}

  uint64_t next() { return engine_(); }
  // Uniform in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  double uniform(double low, double high) { return low + (high - low) * uniform(); }
  // Uniform integer in [0, n), n > 0 (rejection sampling: no modulo bias).
  uint64_t below(uint64_t n);
  // Standard normal (Box-Muller on two uniforms; deterministic, one value per call).
  double normal();
  double normal(double mean, double sigma) { return mean + sigma * normal(); }

  // An independent stream for a named sub-component (e.g. one per generator part), so adding a
  // draw in one part does not shift the numbers of another.
  Rng fork(uint64_t salt) const;

 private:
  std::mt19937_64 engine_;
};

}  // namespace coinspect
