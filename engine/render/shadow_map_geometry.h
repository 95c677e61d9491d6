// The geometry of one shadow map, GL-free: the light's view-projection, which texel size it
// has per metre of distance, how far it reaches, and the rules that pick its resolution.
// Spot maps and point-light cube faces store the distance from the light divided by `far`
// (shaders/shadow_depth.frag), so every depth and bias is in metres.
#pragma once

#include <glm/glm.hpp>

#include "render/frustum.h"
#include "render/shadow_settings.h"
#include "scene/scene.h"

namespace bounce {

struct ShadowView {
  glm::mat4 viewProjection{1.0f};  // world → the map's clip space
  float far = 1.0f;                // metres: stored depth = distance / far
  // Edge of one texel, in metres per metre of distance from the light (at the map's centre,
  // where texels are largest): w(d) = texelAngle · d.
  float texelAngle = 0.0f;
  int resolution = 0;  // texels per side
};

// The half-angle (radians) a spot's map covers: the outer cone (capped at 80°, beyond which a
// perspective map degenerates; the rim beyond is then unshadowed) widened by `marginTexels`
// texels of a `resolution` map so filter taps at the cone's edge stay inside.
float spotMapHalfAngle(const Light& spot, int resolution, float marginTexels);

// Distance (metres) beyond every point of `sceneBox` from `position`, at least 1 mm.
float farDistance(glm::vec3 position, const Box& sceneBox);

// The default resolution: the smallest power of two in [lo, hi] whose texels, at the distance
// from the light to the scene box's centre (at least a quarter of its diagonal), are no larger
// than 1/2048 of the box's diagonal. `span` is the map's width per metre of distance
// (2·tan(half-angle) for a spot, 2 for a cube face).
int defaultShadowResolution(glm::vec3 position, const Box& sceneBox, float span, int lo, int hi);

ShadowView spotShadowView(const Light& spot, const Box& sceneBox, int resolution,
                          float marginTexels);
// Face 0..5 in GL cube-map order (+X, −X, +Y, −Y, +Z, −Z), looking as GL's cube sampling expects.
ShadowView cubeFaceShadowView(glm::vec3 position, int face, const Box& sceneBox, int resolution);

}  // namespace bounce
