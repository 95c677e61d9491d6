// Counter-based random numbers: every value is a pure function of integer keys (seed, pixel,
// sample index, dimension), so a render depends only on those keys and never on the thread
// count or the order in which tiles run. There is no generator state to share or advance.
#pragma once

#include <cstdint>

namespace bounce {

// A 32-bit avalanche mix (the "lowbias32" constants of C. Wellons' hash-prospector): a
// bijection on uint32 whose output bits each depend on every input bit.
inline uint32_t mixBits(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

// Hashes a key and a value into a new key; order matters (hashCombine(a,b) != (b,a)).
inline uint32_t hashCombine(uint32_t key, uint32_t value) {
  return mixBits(key ^ (mixBits(value) + 0x9e3779b9u + (key << 6) + (key >> 2)));
}

inline uint32_t hashKeys(uint32_t a, uint32_t b, uint32_t c) {
  return hashCombine(hashCombine(mixBits(a), b), c);
}

// The top 24 bits as a float in [0,1): exactly representable, never 1.
inline float unitFloat(uint32_t bits) {
  return static_cast<float>(bits >> 8) * 0x1p-24f;
}

// A uniform float in [0,1) keyed by (key, counter).
inline float uniformFloat(uint32_t key, uint32_t counter) {
  return unitFloat(hashCombine(key, counter));
}

}  // namespace bounce
