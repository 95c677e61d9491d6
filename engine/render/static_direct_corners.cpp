#include "render/static_direct_corners.h"

#include <algorithm>
#include <array>
#include <limits>
#include <stdexcept>
#include <string>

#include <tbb/parallel_for.h>

#include "scene/emitter_irradiance.h"

namespace bounce {

namespace {

// Distance (m) from `p` to the nearest of `lights`: an area light's bounding sphere (0 inside),
// a point or spot light's position; a directional light has no near field.
float distanceToLights(const PrecomputedLights& lights, glm::vec3 p) {
  float nearest = std::numeric_limits<float>::infinity();
  for (std::size_t l = 0; l < lights.areaLights(); ++l) {
    if (!lights.areaComputed(l)) continue;
    const AreaLight& light = lights.area->lights[l];
    nearest = std::min(nearest, std::max(glm::length(p - light.centre) - light.radius, 0.0f));
  }
  for (std::size_t i = 0; i < lights.punctual.size(); ++i)
    if (lights.punctualComputed(i) && lights.punctual[i].type != LightType::Directional)
      nearest = std::min(nearest, glm::length(p - lights.punctual[i].position));
  return nearest;
}

}  // namespace

std::vector<glm::vec4> staticDirectCorners(const Scene& scene, const IrradianceProbes& probes,
                                           const PrecomputedLights& lights) {
  const std::vector<TexelVisibility>& corners = probes.visibility.corners;
  std::vector<glm::vec4> direct(3 * corners.size(), glm::vec4(0.0f));
  for (const ProbeGrid& grid : probes.grids) {
    if (grid.cornerCount == 0) continue;
    const Instance& instance = scene.instances.at(grid.instance);
    const Mesh& mesh = scene.meshes.at(instance.mesh);
    if (grid.cornerCount != mesh.indices.size() ||
        static_cast<std::size_t>(grid.firstCorner) + grid.cornerCount > corners.size())
      throw std::invalid_argument("staticDirectCorners: instance " + instance.name +
                                  "'s corners do not match its mesh");
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(instance.transform)));
    tbb::parallel_for(std::size_t{0}, std::size_t{grid.cornerCount / 3}, [&](std::size_t t) {
      glm::vec3 x[3], n[3];
      for (std::size_t k = 0; k < 3; ++k) {
        const uint32_t v = mesh.indices[3 * t + k];
        x[k] = glm::vec3(instance.transform * glm::vec4(mesh.positions[v], 1.0f));
        n[k] = normalMatrix * mesh.normals[v];
        if (!(glm::dot(n[k], n[k]) > 0.0f)) return;  // left per pixel
        n[k] = glm::normalize(n[k]);
      }
      const float edge =
          std::max({glm::length(x[1] - x[0]), glm::length(x[2] - x[1]), glm::length(x[0] - x[2])});
      const glm::vec3 centre = (x[0] + x[1] + x[2]) / 3.0f;
      if (!(edge <= kMaxEdgeOverDistance * distanceToLights(lights, centre))) return;
      for (std::size_t k = 0; k < 3; ++k) {
        const std::size_t corner = grid.firstCorner + 3 * t + k;
        glm::vec3 f[3] = {glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f)};
        addStaticDirect(lights, corners[corner], probes.visibility.lightCount, x[k], n[k], f);
        for (std::size_t c = 0; c < 3; ++c) direct[3 * corner + c] = glm::vec4(f[c], 1.0f);
      }
    });
  }
  return direct;
}

}  // namespace bounce
