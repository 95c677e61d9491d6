// Light culling for the lit pass (GL 3.3 core: no compute shaders, no storage buffers): each
// frame, on the CPU, the view's clusters (cluster_grid.h) get the lights whose reach under the
// cut-off rule (light_cutoff.h) may touch them (light_grid.h), and the lists go into the light
// table's cluster sections (light_table.h). shaders/light_grid.glsl finds a fragment's cluster
// from gl_FragCoord and its view depth and loops over that cluster's lights only.
// Off, every fragment loops over every light, as before; on, a pixel's radiance differs from
// that by at most ρ/π · E_floor per light left out of its cluster (docs/renderer.md).
#pragma once

#include <cstdint>
#include <optional>

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "gl/shader.h"
#include "render/cluster_grid.h"
#include "render/frustum.h"
#include "render/light_culling_settings.h"
#include "render/light_cutoff.h"
#include "render/light_grid.h"
#include "render/light_table.h"
#include "render/punctual_lights.h"
#include "scene/area_lights.h"
#include "scene/scene.h"

namespace bounce {

class LightCulling {
 public:
  explicit LightCulling(const LightCullingSettings& settings) : settings_(settings) {}

  void setSettings(const LightCullingSettings& settings);
  const LightCullingSettings& settings() const { return settings_; }

  // Builds the lists of the frame `camera` sees at width × height over `sceneBox` (world) and
  // hands them to `table` (nothing when off). `areaVersion` changes whenever `area` does. The
  // punctual lights are listed in `punctualOrder` (PunctualLights::listOrder; empty: ascending).
  void update(const Camera& camera, int width, int height, const Box& sceneBox,
              const PunctualLights& punctual, const AreaLightSet& area, int areaVersion,
              LightTable& table, std::span<const uint32_t> punctualOrder = {});
  // Sets the grid's uniforms of shaders/light_grid.glsl (uLightGridEnabled false when off).
  void bind(gl::Program& program) const;

  const LightGridStats& lastFrame() const { return stats_; }
  // How many times the lists were built: a still view whose lights and scene box did not change
  // keeps the last frame's (the camera, the image size, the scene's box, a light's reach or the
  // settings changing rebuilds them).
  uint64_t gridBuilds() const { return gridBuilds_; }
  // The last frame's clusters (the lists are in the light table).
  const ClusterGrid& grid() const { return grid_; }

 private:
  LightCullingSettings settings_;
  std::vector<LightReach> punctualReach_, areaReach_;
  int areaVersion_ = -1;
  bool reachStale_ = true;
  ClusterGrid grid_;
  LightGridStats stats_;
  // What the lists were built for.
  struct BuiltFor {
    glm::mat4 cameraToWorld{0.0f};
    glm::vec4 lens{0.0f};  // yfov, aspect, znear, zfar
    glm::ivec2 size{0};
    Box sceneBox;
    std::vector<LightReach> punctual, area;
    std::vector<uint32_t> punctualOrder;
  };
  std::optional<BuiltFor> builtFor_;
  uint64_t gridBuilds_ = 0;
};

}  // namespace bounce
