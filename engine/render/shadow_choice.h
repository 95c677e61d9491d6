// Which lights get a frame's shadow maps when there are more lights than maps: the ones that
// bring the most light where the maps are read, re-chosen every frame (area cubes:
// area_shadow_budget.h; spot, point and directional maps: punctual_shadow_budget.h). GL-free.
//
// Where a map is read: by the dynamic instances near the view (receivers of every light's
// shadows; casters whose shadow on what they stand on removes about what reaches them), and by
// the visible static surfaces, which points in the visible part of each static, non-emitting
// instance's box stand for.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "render/frustum.h"
#include "scene/box.h"

namespace bounce {

// Where the maps are read, world metres.
struct ShadowReceivers {
  struct Dynamic {
    Box box;
    uint32_t instance = 0;  // an area light's own instance is not ranked at its box (it is lit
                            // by its light, not shadowed: its surface is the light)
  };
  std::vector<Dynamic> dynamics;
  // Points standing for the visible static surfaces (viewSamplePoints); empty when no static
  // surface reads the maps being ranked.
  std::vector<glm::vec3> viewPoints;
  // Each point's share of the screen: about the solid angle (sr) under which the camera sees
  // the surface the point stands for (viewPointWeight). Empty: every point counts the same.
  std::vector<float> viewWeights;
  // Over the view points: Σ w·f(p) / Σ w (the plain mean without weights) and the largest
  // f(p); both 0 without points.
  struct Stats {
    double mean = 0.0, largest = 0.0;
  };
  template <class F>
  Stats viewStats(F&& f) const {
    double sum = 0.0, weights = 0.0, largest = 0.0;
    for (std::size_t i = 0; i < viewPoints.size(); ++i) {
      const double w = i < viewWeights.size() ? viewWeights[i] : 1.0;
      const double value = f(viewPoints[i]);
      sum += w * value;
      weights += w;
      largest = std::max(largest, value);
    }
    return {weights > 0.0 ? sum / weights : 0.0, largest};
  }
};

// The solid angle (sr, at most 1) under which a camera at `eye` sees about `area` m² of surface
// at `p`: area/d², capped where d² < area (the patch fills the view).
float viewPointWeight(glm::vec3 eye, glm::vec3 p, float area);

// The largest f(p) over the points standing for `box` as a receiver: its 8 corners, its centre
// and its point nearest `source` (a light's position or centre).
template <class F>
float largestOverBox(const Box& box, glm::vec3 source, F&& f) {
  float largest = std::max(f(glm::clamp(source, box.lower, box.upper)), f(box.centre()));
  for (int corner = 0; corner < 8; ++corner)
    largest = std::max(largest, f(glm::vec3((corner & 1) ? box.upper.x : box.lower.x,
                                            (corner & 2) ? box.upper.y : box.lower.y,
                                            (corner & 4) ? box.upper.z : box.lower.z)));
  return largest;
}

// perAxis³ grid points of `box` (cell centres) that lie inside `frustum`: the visible volume.
std::vector<glm::vec3> viewSamplePoints(const Frustum& frustum, const Box& box, int perAxis = 4);

struct ShadowChoice {
  std::vector<uint32_t> lights;  // the shadowed lights, largest contribution first
  // Lights at or above the floor left without a map (the slots ran out) and their summed
  // contribution; every light's summed contribution. W/m².
  std::size_t unshadowed = 0;
  double unshadowedContribution = 0.0;
  double totalContribution = 0.0;
  float largestUnshadowed = 0.0f;  // the strongest of them, W/m²
};

// A light's contribution (W/m²) from the most it brings at the dynamic boxes (`atDynamics`) and
// its view statistics: max(atDynamics, view mean), the ranking value; 0 when it reaches `floor`
// nowhere the maps are read (max(atDynamics, the view's largest) < floor): not shaded there at
// all, it needs no map, however little a screen-weighted mean says it brings.
float shadowContribution(float atDynamics, ShadowReceivers::Stats view, float floor);

// At most `slots` lights with contribution ≥ `floor` and > 0 (W/m²), largest first; `previous`
// holds the lights that had a map: a light holding one keeps it against a rival bringing less
// than 10% more (no flicker between near-equal lights as the camera moves).
ShadowChoice chooseShadowedLights(std::span<const float> contributions, int slots, float floor,
                                  std::span<const uint32_t> previous = {});

}  // namespace bounce
