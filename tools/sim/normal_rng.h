#pragma once
#include <cstdint>
#include <random>

namespace deepnav::sim {

// Reproducible random numbers: std::mt19937_64 is fully specified by the standard, but the standard
// distributions are not (libstdc++ and libc++ differ, and may change). So uniforms are built from the
// top 53 bits of the engine and normals by Box-Muller, both here, giving the same stream everywhere.
class NormalRng {
 public:
  NormalRng() : engine_(0) {}
  explicit NormalRng(std::uint64_t seed) : engine_(seed) {}

  // Seed for an independent sub-stream: SplitMix64 of (seed, stream id). Each sensor draws from its own
  // sub-stream, so enabling or reconfiguring one sensor does not change the noise of another.
  static std::uint64_t subSeed(std::uint64_t seed, std::uint64_t stream_id);

  // Uniform in (0, 1]: never 0, so log() in Box-Muller is finite.
  double uniform();
  // Standard normal N(0, 1).
  double normal();
  double normal(double sigma) { return sigma * normal(); }

 private:
  std::mt19937_64 engine_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace deepnav::sim
