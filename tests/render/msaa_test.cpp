// Multisample anti-aliasing (gl/render_target.h): a pixel on a surface's edge reads the
// surface's radiance times the share of the pixel it covers (a box filter, as the path tracer
// filters its pixels), computed exactly here by clipping the projected quad to each pixel; and
// the edge pixels' shading stays on the surface (centroid interpolation): their lightmap lookup
// never reaches the chart's surroundings.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "gl/render_target.h"
#include "lightmap_scenes.h"
#include "support/clipped_area.h"
#include "test_scenes.h"

namespace bounce::test {
namespace {

constexpr float kPi = 3.14159265358979f;
constexpr int kSize = 32;
constexpr float kHalfSide = 0.25f;  // m: the quad is 0.5 m wide
constexpr float kTurn = 0.5236f;    // rad (30°) about the vertical: no edge runs along a pixel row
constexpr float kRho = 0.5f;
constexpr float kIrradiance = 2.0f;  // W/m², inside the chart and its one texel of padding
constexpr float kOutside = 1000.0f;  // W/m², every other texel: a lookup off the chart shows

glm::vec3 corner(int i) {  // counter-clockwise seen from above (+y), rotated by kTurn
  const glm::vec2 local[4] = {{-1, 1}, {1, 1}, {1, -1}, {-1, -1}};
  const float c = std::cos(kTurn), s = std::sin(kTurn);
  const glm::vec2 p = kHalfSide * local[i];
  return {c * p.x - s * p.y, 0.0f, s * p.x + c * p.y};
}

struct QuadScene {
  Scene scene;
  Camera camera = downCamera(1.0f);
  Bake bake;
};

// The quad's atlas region is [0.25, 0.75]² of a 64² lightmap: texels 16–47 cover it, texels 15
// and 48 are its padding (E as inside, so a bilinear lookup on the quad reads E exactly), every
// other texel kOutside.
QuadScene quadScene() {
  QuadScene q;
  Material m;
  m.name = "quad";
  m.albedo = glm::vec3(kRho);
  Mesh mesh;
  mesh.name = "quad";
  for (int i = 0; i < 4; ++i) {
    mesh.positions.push_back(corner(i));
    mesh.normals.push_back({0, 1, 0});
  }
  mesh.uv0 = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  mesh.indices = {0, 1, 2, 0, 2, 3};
  addMesh(q.scene, mesh, m);
  const glm::vec2 uv[4] = {{0.25f, 0.25f}, {0.75f, 0.25f}, {0.75f, 0.75f}, {0.25f, 0.75f}};
  Image irradiance(64, 64, glm::vec3(kOutside));
  for (int y = 15; y <= 48; ++y)
    for (int x = 15; x <= 48; ++x) irradiance.at(x, y) = glm::vec3(kIrradiance);
  q.bake.layout.width = q.bake.layout.height = 64;
  q.bake.layout.texelSize = 1.0f / 64.0f;
  InstanceLightmapUv region{0, {}};
  for (uint32_t index : mesh.indices) region.cornerUv.push_back(uv[index]);
  q.bake.layout.instances = {region};
  q.bake.irradiance = irradiance;
  q.bake.manifest = minimalManifest(q.scene);
  return q;
}

// downCamera(1) maps the floor point (x, 0, z) to the raster point ((x/t + 1)·W/2,
// (z/t + 1)·H/2), t = tan(yfov/2): linear, so the quad projects to a parallelogram.
glm::vec2 raster(const Camera& camera, glm::vec3 p) {
  const float t = std::tan(0.5f * camera.yfov);
  return {(p.x / t + 1.0f) * 0.5f * kSize, (p.z / t + 1.0f) * 0.5f * kSize};
}

// Area of the convex polygon `poly` inside the pixel [x, x+1] × [y, y+1].
double coverage(const std::vector<glm::dvec2>& poly, int x, int y) {
  return clippedArea(poly, glm::dvec2(x, y), glm::dvec2(x + 1, y + 1));
}

struct EdgeFigures {
  double meanEdgeError = 0.0;   // mean over partly covered pixels of |L/L_quad − coverage|
  double maxOverQuad = 0.0;     // largest L/L_quad of any pixel (1: nothing off the chart)
  double maxOffCoverage = 0.0;  // largest |L/L_quad − coverage| over fully in or out pixels
  double sumError = 0.0;        // (Σ L/L_quad − Σ coverage) / Σ coverage
  int edgePixels = 0;
};

EdgeFigures measure(int samples) {
  const QuadScene q = quadScene();
  testContext();
  RendererSettings settings;
  settings.mode = RenderMode::Indirect;
  ForwardRenderer renderer(q.scene, gl::shaderDirectory(), settings, &q.bake);
  const Image image = renderer.renderImage(q.camera, kSize, kSize, samples);
  std::vector<glm::dvec2> poly;
  for (int i = 0; i < 4; ++i) poly.push_back(glm::dvec2(raster(q.camera, corner(i))));
  const double quadRadiance = kRho / kPi * kIrradiance;  // W/(sr·m²)
  EdgeFigures f;
  double sum = 0.0, covered = 0.0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const double c = coverage(poly, x, y);
      const double v = image.at(x, y).g / quadRadiance;
      sum += v;
      covered += c;
      f.maxOverQuad = std::max(f.maxOverQuad, v);
      if (c > 1e-6 && c < 1.0 - 1e-6) {
        f.meanEdgeError += std::abs(v - c);
        ++f.edgePixels;
      } else {
        f.maxOffCoverage = std::max(f.maxOffCoverage, std::abs(v - c));
      }
    }
  f.meanEdgeError /= std::max(f.edgePixels, 1);
  f.sumError = (sum - covered) / covered;
  return f;
}

// With 4 samples a pixel's value estimates its coverage c from 4 points: for an edge crossing the
// pixel at random, E|k/4 − c| is about 1/16 for a rotated-grid pattern, against E|round(c) − c|
// = 1/4 for one sample at the centre. Measured on llvmpipe over the quad's 100 edge pixels:
// 0.058 with 4 samples, 0.18 with one; 0.1 and 0.12 separate them. Every pixel stays at or
// under the quad's radiance: an edge pixel shaded at its centre, off the quad, would read the
// kOutside texels (measured: the sum over the frame is the covered area within 1e-4).
TEST(Msaa, EdgePixelsReadTheirCoverageAndStayOnTheSurface) {
  const EdgeFigures f = measure(4);
  ASSERT_GT(f.edgePixels, 40);
  EXPECT_LT(f.meanEdgeError, 0.1) << f.edgePixels << " edge pixels";
  EXPECT_LE(f.maxOverQuad, 1.0 + 1e-4);
  EXPECT_LT(f.maxOffCoverage, 1e-4);
  EXPECT_LT(std::abs(f.sumError), 0.01);
}

// One sample per pixel (--msaa 1) is no anti-aliasing: each pixel is the quad's or black.
TEST(Msaa, OneSampleIsOff) {
  const EdgeFigures f = measure(1);
  EXPECT_GT(f.meanEdgeError, 0.12);
  EXPECT_LE(f.maxOverQuad, 1.0 + 1e-4);
  EXPECT_LT(f.maxOffCoverage, 1e-4);
}

TEST(Msaa, MoreSamplesThanTheDriverHasAreRefused) {
  testContext();
  const int most = gl::RenderTarget::maxSamples();
  EXPECT_GE(most, 4);  // GL 3.3 core requires it
  try {
    gl::RenderTarget target(8, 8, most + 1);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("the driver allows 1 to " + std::to_string(most)),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace bounce::test
