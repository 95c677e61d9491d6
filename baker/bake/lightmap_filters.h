// Image passes on a baked lightmap (texel values E in W/m²; texel space as in
// engine/bake_folder/lightmap_layout.h, texel (x, y) centred at (x + ½, y + ½)). Pure functions of
// their inputs, easy to test on small images.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "bake_folder/lightmap_layout.h"
#include "image/image.h"
#include "scene/scene.h"
#include "scene/world_geometry.h"

namespace bounce {

// Connected components (8-neighbourhood) of the texels with mask ≠ 0, labelled 1, 2, … in
// scan order; 0 elsewhere. Charts are packed with ≥ 2 texels between them, so each label lies
// inside one chart.
std::vector<uint32_t> labelCharts(int width, int height, const std::vector<uint8_t>& mask);

// One round of dilation: every texel with filled == 0 and at least one filled 8-neighbour
// (of the same label when `labels` is given) takes their mean and becomes filled. Returns how
// many texels it filled.
std::size_t dilateOnce(Image& image, std::vector<uint8_t>& filled,
                       const std::vector<uint32_t>* labels = nullptr);

// Texels the adaptive stop left at exactly 0 before the sample cap (texel_irradiance.h,
// zeroSamplesToStop) know only that a sample finds light with probability under 3/n: in a dim
// closed room lit through a door (1–3% of the samples find light) 128 zero samples happen to
// about one texel in twenty, which would show as black specks among lit neighbours. Each such
// texel (`unresolved` ≠ 0) with a lit-or-resolved 8-neighbour of its label takes their mean, for
// up to `rings` rounds, and its relative error becomes 1 (the denoiser then leans on its
// neighbours); an unresolved texel with none within `rings` (a roof no lamp reaches) stays 0.
// `invalid` texels (the leak guard's, not yet filled) are neither used nor filled. Returns how
// many texels it filled.
std::size_t fillUnresolvedZeros(Image& image, const std::vector<uint8_t>& unresolved,
                                const std::vector<uint8_t>& invalid,
                                const std::vector<uint32_t>& labels,
                                std::vector<float>& relativeError, int rings = 2);

// Bilinear lookup at texel-space point p (clamped at the borders), the renderer's filter.
glm::vec3 bilinear(const Image& image, glm::vec2 p);

// A chart border that is one edge in 3D: the same two world points (and normals) at different
// atlas positions. a0/b0 are the texel-space images of the first world point, a1/b1 of the
// second.
struct Seam {
  glm::vec2 a0, a1;
  glm::vec2 b0, b1;
};

// Edges of lightmapped triangles whose endpoints share world positions (to 1e-5 m) and shading
// normals (cos ≥ 0.99) with another triangle's edge but whose atlas UVs differ; never where
// another surface crosses this one (Mesh::cutEdges: a wall's foot between the two sides).
std::vector<Seam> findSeams(const Scene& scene, const WorldGeometry& geometry,
                            const LightmapLayout& layout);

// Adjusts the texels under each seam (least change, Kaczmarz sweeps) so that bilinear lookups at
// matching points on both sides agree: points every half texel along each seam. Returns the
// largest remaining |difference| relative to the larger of the two lookups' luminance. The
// sweeps are linear in the image; texels pushed below 0 are then clamped to 0 (irradiance),
// unless `clampAtZero` is false (a signed image, such as a half-sample difference).
float stitchSeams(Image& image, const std::vector<Seam>& seams, int iterations = 64,
                  bool clampAtZero = true);

// Largest |bilinear(side a) − bilinear(side b)| (luminance) over the seams' points, W/m².
float largestSeamJump(const Image& image, const std::vector<Seam>& seams);

// Edge-aware à-trous denoiser (up to 4 passes of a 5×5 B3-spline kernel, steps 1, 2, 4, 8; a
// step longer than maxStepMetres on the surface is skipped), guided per texel by world position
// (σ = step × texel size), normal (cos³²) and chart label; never mixes texels of different
// labels, and weighs luminance differences by a Gaussian of 2 combined standard errors, each
// texel's variance being (relativeError × value)² at first and then the variance of the weighted
// mean it became, carried through the passes: differences the remaining noise cannot explain
// stay. Texels with label 0 are left alone and never used.
struct DenoiseGuide {
  std::vector<glm::vec3> position;  // world, metres (mean of the texel's points)
  std::vector<glm::vec3> normal;    // unit
  std::vector<uint32_t> label;      // chart label, 0 = skip
  std::vector<float> relativeError;
  float texelSize = 0.0f;  // metres
  // A pass whose step spans more than this on the surface is skipped (irradiance gradients have
  // a world-space scale).
  float maxStepMetres = 0.61f;
};
// `alongside`, when given (same size), gets the same weighted means as `image`, with the weights
// `image` decided: the one linear filter applied to both (delivered_error.h).
void denoise(Image& image, const DenoiseGuide& guide, Image* alongside = nullptr);

}  // namespace bounce
