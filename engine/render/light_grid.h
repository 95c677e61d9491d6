// Which lights each cluster of the view (render/cluster_grid.h) must shade: a light joins every
// cluster its reach (render/light_cutoff.h) may touch, so a fragment loops over its cluster's
// list instead of every light. GL-free; render/light_grid_pass.h uploads the lists.
//
// The lists, as the light table's cluster sections hold them (shaders/light_grid.glsl):
//
//   headers  one texel per cluster: (first entry, punctual count, area count, 0)
//   entries  4 per texel, entry k at texel k/4, component k%4: per cluster its punctual lights'
//            indices then its area lights' indices, ascending
//
// Indices are the lights' own (light-table row, area-light row), so shadow slots and baked
// visibility, which the shader reads by index, are unchanged. Floats: exact below 2^24.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "render/cluster_grid.h"
#include "render/frustum.h"

namespace bounce {

// Where a light may give a point E ≥ E_floor (world space, metres).
struct LightReach {
  enum class Shape {
    None,        // gives nothing (zero power): in no cluster
    Everywhere,  // directional: in every cluster
    Sphere,      // within `radius` of `centre`
    Cone,        // the sphere, and within the outer cone: apex `centre`, unit `axis`
    Box,         // within `radius` of `box`
  };
  Shape shape = Shape::None;
  glm::vec3 centre{0.0f};
  float radius = 0.0f;
  glm::vec3 axis{0.0f, 0.0f, -1.0f};
  float cosOuter = 1.0f, sinOuter = 0.0f;  // cone half-angle
  Box box;
};

struct LightGridLists {
  std::vector<glm::vec4> headers;  // one per cluster
  std::vector<glm::vec4> entries;  // 4 indices per texel
  std::size_t punctualEntries = 0, areaEntries = 0;
  std::size_t maxPunctual = 0, maxArea = 0;  // longest list in a cluster
};

// Whether `reach` may touch `cluster` (view space, as ClusterGrid::clusterBox). Conservative:
// false only when no point of the cluster lies within the reach.
bool reachTouches(const LightReach& reachInView, const Box& cluster);

// `reach` (world) in the view space of `view` (rigid): centre and axis moved, the box as the
// box around its moved corners.
LightReach toView(const LightReach& reach, const glm::mat4& view);

LightGridLists assignLights(const ClusterGrid& grid, std::span<const LightReach> punctual,
                            std::span<const LightReach> area,
                            std::span<const uint32_t> punctualOrder = {});

}  // namespace bounce
