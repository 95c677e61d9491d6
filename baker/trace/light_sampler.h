// One light sampler over every light the tracer knows: the area emitters (as one entry whose
// triangles the EmitterTable picks by power), the scene's punctual lights (point, spot,
// directional) and optional virtual point lights. Next-event estimation picks ONE light per
// path vertex with probability proportional to its power (luminance of the flux, W):
//   area emitters  Σ π·A·luminance(Le) (×2 double-sided)   = luminance(EmitterTable::power())
//   point          4π · luminance(I)
//   spot           2π(1 − cos outer) · luminance(I)  (the full outer cone: an upper bound of
//                  the power under the t² falloff, cheap and never zero where the spot lights)
//   directional    luminance(E) · π R², R the radius of the scene's bounding sphere (centre
//                  of the bounding box of the finite vertices, half its diagonal): the flux
//                  through the disc the scene presents to the light, an upper bound of what
//                  the scene can receive
//   virtual point  luminance(Φ) (a cosine emitter radiates its whole Φ into its hemisphere)
// Lights whose power is zero or not finite are never picked. Any positive weights give an
// unbiased estimator as long as the pmf used to divide is the one sampled from (pmf()).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "bake_folder/vpl.h"
#include "scene/scene.h"
#include "scene/world_geometry.h"
#include "trace/emitters.h"

namespace bounce {

enum class LightKind : uint8_t { Area, Punctual, Virtual };

struct LightPick {
  LightKind kind = LightKind::Area;
  uint32_t index = 0;     // Punctual: into Scene::lights; Virtual: into the VPL span; Area: 0
  float pmf = 0.0f;       // probability of this pick
  float remapped = 0.0f;  // u rescaled to [0,1) inside the picked entry: a fresh uniform number
};

class LightSampler {
 public:
  // `emitters` and `vpls` must outlive the sampler.
  LightSampler(const Scene& scene, const WorldGeometry& geometry, const EmitterTable& emitters,
               std::span<const Vpl> vpls);

  bool empty() const { return entries_.empty(); }
  std::size_t size() const { return entries_.size(); }
  // Picks an entry by inverting the CDF at u ∈ [0,1). Precondition: !empty().
  LightPick pick(float u) const;
  // Probability of picking the area emitter set (0 when there is none); the pmf of one emitter
  // triangle is areaPmf() × its EmitterTable pmf.
  float areaPmf() const { return areaPmf_; }
  // Radius R of the scene's bounding sphere (m) used for directional lights' power.
  float sceneRadius() const { return sceneRadius_; }
  // Luminance of the power of scene light i (W), as defined above; 0 when never picked.
  static float punctualPower(const Light& light, float sceneRadius);

 private:
  struct Entry {
    LightKind kind;
    uint32_t index;
  };
  std::vector<Entry> entries_;
  std::vector<double> cdf_;  // cdf_[i] = Σ_{j<i} pmf_j, cdf_.back() = 1
  std::vector<float> pmf_;
  float areaPmf_ = 0.0f;
  float sceneRadius_ = 0.0f;
};

// The radius of the bounding sphere (centre of the bounding box, half its diagonal) of the
// finite vertices, metres; 0 for no geometry.
float boundingSphereRadius(const WorldGeometry& geometry);

}  // namespace bounce
