// Cascaded shadow maps for a directional light: where each cascade's orthographic map lies.
// GL-free (the shadow pass draws with these matrices; shaders/shadow_directional.glsl samples
// them). Lengths in metres; "view depth" is the distance along the camera's forward axis.
//
// The camera's visible depth range [near, far] is cut at split depths s_0 < … < s_N (the
// practical split scheme, a blend of logarithmic and uniform). Cascade i covers the frustum slice
// [s_i − b_i, s_{i+1}], where b_i = blendFraction·(s_i − s_{i−1}) is the band at the far end of
// cascade i−1 in which the shader cross-fades into cascade i (b_0 = 0), so the blend band lies in
// both maps.
//
// Invariants (tests/render/cascades_test.cpp):
//   - the box of cascade i contains every point of its slice (across the light, and in depth);
//   - the box's side depends only on the slice's depths, the field of view and the aspect (the
//     slice's bounding sphere, not its rotated bounding box), so it never changes as the camera
//     turns or moves;
//   - the box's lower corner across the light is a whole number of texels from the light-space
//     origin (texel snapping): a camera move shifts the map by whole texels, every world point
//     keeps its position inside its texel, and the stored depths do not shimmer. A camera moved by
//     less than a texel moves the box by at most one texel per axis, and not at all while the
//     slice's centre stays inside the same texel.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "scene/framing.h"
#include "scene/scene.h"

namespace bounce {

struct CascadeSettings {
  int count = 4;               // cascades, 1..kMaxCascades
  int resolution = 2048;       // texels per side of each cascade's square map
  float splitLambda = 0.75f;   // 1 = logarithmic splits, 0 = uniform
  float blendFraction = 0.1f;  // share of the previous slice's depth used to cross-fade, 0..0.5
};

inline constexpr int kMaxCascades = 4;

struct Cascade {
  float nearDepth = 0.0f;     // view depth where this cascade starts (its blend band included)
  float splitDepth = 0.0f;    // view depth where it hands over to the next (s_{i+1})
  float blendStart = 0.0f;    // view depth where the cross-fade into the next cascade starts
  glm::mat4 lightView{1.0f};  // world → light space: a rotation only; −z is the light direction
  glm::mat4 projection{1.0f};              // light space → clip, orthographic
  glm::mat4 worldToClip{1.0f};             // projection · lightView
  glm::dvec2 boxMin{0.0};                  // lower corner across the light, light-space metres
  glm::dvec3 centre{0.0};                  // world centre of the slice's bounding sphere, metres
  double radius = 0.0;                     // that sphere's radius, metres
  double boxSide = 0.0;                    // box width = height, metres = resolution · texelSize
  double texelSize = 0.0;                  // metres per texel
  double depthNear = 0.0, depthFar = 0.0;  // light-space depth range (metres along the light)
};

// The split depths s_0 = znear < s_1 < … < s_count = zfar (count + 1 values), metres.
std::vector<float> cascadeSplits(float znear, float zfar, int count, float lambda);

// World → light space: a right-handed rotation whose −z axis is `lightDirection` (the way light
// travels) and whose x axis stays horizontal; a function of the direction alone, so the texel
// grid is fixed in the world while the camera moves.
glm::dmat3 lightRotation(glm::vec3 lightDirection);

// The view-depth range worth covering: from the camera's znear to the farthest depth of the
// scene bounds (a 1000 m zfar over a 20 m room would waste every cascade), that far end rounded up
// to a power of 2^(1/4) so it stays put while the camera moves; never beyond zfar. Empty bounds
// keep the camera's clip range.
glm::vec2 coveredDepthRange(const Camera& camera, const Bounds& bounds);

// The cascades of a directional light for `camera` with an image of width/height `aspect`.
// `bounds` (the scene's) widens each box's depth range so that casters between the light and the
// slice are in the map.
std::vector<Cascade> fitCascades(const Camera& camera, float aspect, glm::vec3 lightDirection,
                                 const Bounds& bounds, const CascadeSettings& settings);

// The eight world corners of the frustum slice between view depths `nearDepth` and `farDepth`.
std::vector<glm::dvec3> frustumSliceCorners(const Camera& camera, float aspect, double nearDepth,
                                            double farDepth);

}  // namespace bounce
