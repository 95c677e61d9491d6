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
//
// pickAt() chooses by place instead, for next-event estimation at a surface point p with unit
// geometric normal n: among the area emitters' clusters (trace/emitters.h) and the punctual
// lights, with weight w_i, a bound of the irradiance (W/m²) light i can bring to p, and zero
// where it brings none for certain:
//   cluster        (Φ/π) / max(d², r²)   Φ/π = Σ A·Le (× 2 double-sided) bounds its intensity
//                                        (W/sr), d from p to its bounding sphere's centre, r
//                                        its radius; 0 when the sphere lies below p's plane
//   point          I / max(d², 1 cm²)    0 when the light is below p's plane
//   spot           as point, and 0 outside the outer cone (where the falloff is 0)
//   directional    E                     0 when it arrives from below p's plane
// and pmf_i = (1 − α)·w_i/Σw + α·P_i/Σ P_j over the lights with w > 0 (P: power as above,
// α = kPowerShare), so a light whose bound misleads (it is occluded, its cluster is wide) keeps
// a share by power. The zeros are exact: the tracer's estimates from those lights are 0 there
// (they test the same geometric normal). With virtual point lights, or more than
// kMaxNearbyLights entries, pickAt() is pick().
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

inline constexpr std::size_t kMaxNearbyLights = 128;
inline constexpr float kPowerShare = 0.1f;  // α above

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
  // Whether pickAt() chooses by place (above).
  bool choosesByPlace() const { return !nearby_.empty(); }
  // Picks by place at `position` (m) with unit geometric normal `normal`; Area picks name an
  // emitter cluster (EmitterTable::clusters()) in `index`. pmf 0 when no light can reach it.
  LightPick pickAt(float u, glm::vec3 position, glm::vec3 normal) const;
  // The probability with which pickAt() at that point picks emitter cluster c.
  float clusterPmfAt(uint32_t cluster, glm::vec3 position, glm::vec3 normal) const;
  // Radius R of the scene's bounding sphere (m) used for directional lights' power.
  float sceneRadius() const { return sceneRadius_; }
  // Luminance of the power of scene light i (W), as defined above; 0 when never picked.
  static float punctualPower(const Light& light, float sceneRadius);

 private:
  struct Entry {
    LightKind kind;
    uint32_t index;
  };
  // A light pickAt() chooses among: an emitter cluster or a punctual light.
  struct Nearby {
    LightKind kind;
    uint32_t index;          // cluster, or into Scene::lights
    LightType type;          // Punctual only
    glm::vec3 position;      // cluster centre or light position, m
    glm::vec3 direction;     // unit direction the light travels (spot, directional)
    float radius = 0.0f;     // cluster radius, m
    float cosOuter = -1.0f;  // spot
    float intensity = 0.0f;  // luminance: W/sr bound (cluster, point, spot), W/m² (directional)
    float power = 0.0f;      // luminance, W
  };
  void addNearby(const Scene& scene, const EmitterTable& emitters);
  // Fills w (nearby_.size() entries) and returns the probabilities' two sums in the mixture.
  void nearbyWeights(glm::vec3 position, glm::vec3 normal, float* w, float& weightSum,
                     float& powerSum) const;
  float nearbyPmf(std::size_t i, const float* w, float weightSum, float powerSum) const;

  std::vector<Nearby> nearby_;
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
