// The low-discrepancy sampler: per-dimension-pair Owen-scrambled Sobol (0,2)-sequences with
// hash-based nested uniform scrambling and index shuffling (B. Burley, "Practical Hash-based
// Owen Scrambling", JCGT 2020).
//
// Each 2D request uses the first two Sobol dimensions (van der Corput and its Pascal-matrix
// partner, which together form a (0,2)-sequence in base 2). Independent pairs are obtained by
// seeding the scramble and the index shuffle with hash(seed, pixel, dimension):
//   * for every m, the first 2^m samples of a pair form a (0,m,2)-net: every elementary
//     interval [a/2^i, (a+1)/2^i) × [b/2^j, (b+1)/2^j) with i+j = m holds exactly one point;
//   * each point is uniformly distributed on [0,1)² (Owen scrambling), so estimates are
//     unbiased, and the error of smooth integrands falls like N^(−3/2) rather than N^(−1/2);
//   * values depend only on (seed, pixel, sample index, dimension): deterministic under any
//     thread count or schedule.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace bounce {

uint32_t reverseBits(uint32_t x);
// Sobol dimensions 0 and 1 as 32-bit fixed point fractions of [0,1).
uint32_t sobolDimension0(uint32_t index);
uint32_t sobolDimension1(uint32_t index);
// Owen scrambling of a 32-bit fraction: bit k (from the top) is flipped by a hash of `seed`
// and the bits above it, a random nested uniform permutation of the base-2 digits.
uint32_t nestedUniformScramble(uint32_t x, uint32_t seed);

class SobolSampler {
 public:
  // One pattern per (seed, pixel); `pixel` is any integer that identifies the estimate
  // (pixel index, texel index, ...).
  SobolSampler(uint32_t seed, uint32_t pixel);

  // Selects sample `index` of the pattern and rewinds to dimension 0.
  void startSample(uint32_t index) {
    index_ = index;
    dimension_ = 0;
  }
  // Dimensions count 2D pairs; a 1D request uses (and consumes) a whole pair.
  uint32_t dimension() const { return dimension_; }
  void setDimension(uint32_t dimension) { dimension_ = dimension; }
  uint32_t sampleIndex() const { return index_; }

  glm::vec2 get2D();
  float get1D();

  // For tests of the dimension allocation: while set, the index of every pair drawn is
  // appended to *log, so a test can check that no two decisions of one sample share a pair.
  void logDimensions(std::vector<uint32_t>* log) { log_ = log; }

 private:
  glm::uvec2 pairBits();
  // The scramble seeds of pair d (index shuffle, x, y): functions of (seed, pixel, d) only,
  // so they are cached for the first pairs and reused by every sample of the pattern.
  glm::uvec3 pairSeeds(uint32_t d);

  static constexpr uint32_t kCachedPairs = 32;
  uint32_t patternSeed_;
  uint32_t index_ = 0;
  uint32_t dimension_ = 0;
  uint32_t cached_ = 0;  // bit d set: seeds_[d] is valid
  std::array<glm::uvec3, kCachedPairs> seeds_;
  std::vector<uint32_t>* log_ = nullptr;
};

}  // namespace bounce
