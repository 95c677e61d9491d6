// Area lights as the shadow passes see them: the emissive triangles of one instance and one
// material form one light (the Cornell box's ceiling quad is one), shadowed by one depth cube map
// from its centre and percentage-closer soft shadows (shaders/shadow_area.glsl). GL-free.
// Lengths in metres, radiance W/(sr·m²), flux W per linear-RGB channel.
//
// The unshadowed irradiance stays the exact polygon integral of shaders/area_light.glsl; the map
// only supplies the visible fraction V of the light, estimated from K fixed points x_k spread
// evenly over the light's area (samplePoints): a receiver p whose blockers lie at distance d_B
// from the centre sees x_k through the point where the segment p→x_k crosses that distance, so
// the filter region is the light's own shape shrunk by (d_R − d_B)/d_R about p's direction, and
// the penumbra widens with the distance between occluder and receiver as in the path tracer.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace bounce {

// One emissive triangle as the forward pass's emitter table holds it.
struct EmitterTriangle {
  glm::vec3 v0, v1, v2;  // world, metres, counter-clockwise = the emitting front face
  glm::vec3 radiance;    // W/(sr·m²)
  bool doubleSided = false;
  uint32_t instance = 0;  // Scene::instances index
  uint32_t material = 0;  // Scene::materials index
};

struct AreaLight {
  std::vector<uint32_t> triangles;  // indices into the emitter list it was grouped from
  uint32_t instance = 0, material = 0;
  glm::vec3 centre{0.0f};  // area-weighted centroid, metres
  glm::vec3 normal{0.0f};  // unit area-weighted front normal; 0 when the faces cancel (closed)
  float area = 0.0f;       // m²
  float radius = 0.0f;     // largest distance of a vertex from the centre, metres
  glm::vec3 flux{0.0f};    // W emitted: Σ π·L·A (×2 when double-sided)
  bool doubleSided = false;
};

// Groups emitters by (instance, material), in order of first appearance.
std::vector<AreaLight> groupAreaLights(const std::vector<EmitterTriangle>& emitters);

// The lights given a shadow map: at most `maxShadowed`, the largest total flux first (ties: the
// earlier light); returns their indices into `lights`, in that order.
std::vector<uint32_t> pickShadowedAreaLights(const std::vector<AreaLight>& lights, int maxShadowed);

// `count` points spread evenly over the light's area (a Hammersley set mapped onto its triangles
// by area), world metres: each stands for an equal share of the light's area.
std::vector<glm::vec3> samplePoints(const AreaLight& light,
                                    const std::vector<EmitterTriangle>& emitters, int count);

}  // namespace bounce
