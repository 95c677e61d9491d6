#include "trace/sobol_sampler.h"

#include "trace/rng.h"

namespace bounce {

uint32_t reverseBits(uint32_t x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
  return __builtin_bswap32(x);
}

// Dimension 0: bit k of the index becomes the k-th binary digit after the point.
uint32_t sobolDimension0(uint32_t index) {
  return reverseBits(index);
}

// Dimension 1: primitive polynomial x+1, direction numbers v_1 = 1/2, v_k = v_{k−1} ⊕
// (v_{k−1} >> 1), i.e. the rows of Pascal's triangle mod 2 (0.1, 0.11, 0.101, 0.1111, ...).
namespace {

// The product with the generator matrix, one byte of the index at a time:
// table[b][k] = XOR of the direction numbers v_{8b+j+1} for the set bits j of k.
struct Dimension1Tables {
  uint32_t table[4][256];
  Dimension1Tables() {
    uint32_t direction[32];
    direction[0] = 1u << 31;
    for (int i = 1; i < 32; ++i) direction[i] = direction[i - 1] ^ (direction[i - 1] >> 1);
    for (int b = 0; b < 4; ++b) {
      for (uint32_t k = 0; k < 256; ++k) {
        uint32_t x = 0;
        for (int j = 0; j < 8; ++j) {
          if (k & (1u << j)) x ^= direction[8 * b + j];
        }
        table[b][k] = x;
      }
    }
  }
};

const Dimension1Tables kDimension1;

}  // namespace

uint32_t sobolDimension1(uint32_t index) {
  return kDimension1.table[0][index & 0xffu] ^ kDimension1.table[1][(index >> 8) & 0xffu] ^
         kDimension1.table[2][(index >> 16) & 0xffu] ^ kDimension1.table[3][index >> 24];
}

namespace {

// Laine–Karras style permutation: x ↦ x ⊕ (x·c) with even c flips bit j by a function of the
// bits below j only, so on bit-reversed values it is a nested uniform scramble. Constants
// from Burley 2020.
uint32_t laineKarrasPermutation(uint32_t x, uint32_t seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

}  // namespace

uint32_t nestedUniformScramble(uint32_t x, uint32_t seed) {
  return reverseBits(laineKarrasPermutation(reverseBits(x), seed));
}

SobolSampler::SobolSampler(uint32_t seed, uint32_t pixel)
    : patternSeed_(hashKeys(seed, pixel, 0x50b01u)) {}

glm::uvec3 SobolSampler::pairSeeds(uint32_t d) {
  auto compute = [this](uint32_t dim) {
    const uint32_t pairSeed = hashCombine(patternSeed_, dim);
    return glm::uvec3(pairSeed, hashCombine(pairSeed, 1u), hashCombine(pairSeed, 2u));
  };
  if (d >= kCachedPairs) return compute(d);
  if (!((cached_ >> d) & 1u)) {
    seeds_[d] = compute(d);
    cached_ |= 1u << d;
  }
  return seeds_[d];
}

glm::uvec2 SobolSampler::pairBits() {
  if (log_ != nullptr) log_->push_back(dimension_);
  const glm::uvec3 seeds = pairSeeds(dimension_++);
  // Shuffling the index by a nested uniform scramble keeps every power-of-two prefix a
  // (0,m,2)-net (the low m bits of the shuffled index are a permutation of the low m bits),
  // while decorrelating this pair from the others.
  //   shuffled = nestedUniformScramble(index) = reverse(LK(reverse(index)))
  //   x = nestedUniformScramble(sobolDimension0(shuffled)) = reverse(LK(shuffled))
  // since sobolDimension0 = reverse: written with the reversals that cancel removed.
  const uint32_t shuffled = reverseBits(laineKarrasPermutation(reverseBits(index_), seeds.x));
  return {reverseBits(laineKarrasPermutation(shuffled, seeds.y)),
          nestedUniformScramble(sobolDimension1(shuffled), seeds.z)};
}

glm::vec2 SobolSampler::get2D() {
  const glm::uvec2 bits = pairBits();
  return {unitFloat(bits.x), unitFloat(bits.y)};
}

float SobolSampler::get1D() {
  return unitFloat(pairBits().x);
}

}  // namespace bounce
