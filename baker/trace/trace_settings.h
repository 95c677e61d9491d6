// Settings of the path tracer and the reference renderer.
#pragma once

#include <cstdint>

#include "bake_folder/light_choice.h"
#include "ray/ray_kernel.h"

namespace bounce {

// Which light paths are counted, by their number of diffuse reflections k:
//   All: every k in [0, maxDepth];
//   DirectOnly: k ≤ 1 (emitters seen directly + light after one reflection: what the forward
//               renderer draws live);
//   IndirectOnly: k ≥ 2 (the rest). DirectOnly + IndirectOnly = All.
enum class PathSet : uint8_t { All, DirectOnly, IndirectOnly };

// How light reaching a surface from area emitters is estimated. Delta lights (point, spot,
// directional) can only be reached by light sampling and always are.
enum class LightStrategy : uint8_t {
  Mis,        // light sampling + BRDF sampling, power heuristic (the default)
  LightOnly,  // next-event estimation only; emitters hit by bounce rays are ignored
  BrdfOnly,   // emitters count only when a BRDF-sampled ray hits them
};

struct TraceSettings {
  int spp = 64;           // samples per pixel
  int maxDepth = 64;      // most diffuse reflections along a path (0: emitters seen directly)
  int rouletteDepth = 3;  // Russian roulette from this many reflections on
  PathSet paths = PathSet::All;
  LightStrategy strategy = LightStrategy::Mis;
  LightChoice lightChoice = LightChoice::ByPlace;
  uint32_t seed = 0;
  int threads = 0;                          // 0: all cores (TBB's default)
  RayBackend backend = RayBackend::Embree;  // used by callers that build the kernel
  // Firefly clamp: when > 0, each sample's radiance (except emitters seen directly) is
  // scaled so that its largest channel is at most this, W/(sr·m²). Biased (darker); off
  // by default.
  float clampRadiance = 0.0f;
  bool progress = false;  // live progress line on stderr
};

}  // namespace bounce
