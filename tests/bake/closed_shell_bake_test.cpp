// The conference room's black chairs in miniature: a closed slab wound inside out (every
// triangle facing into it, as the room's chair backs are exported) stands in a closed room
// lit by a point light. The path tracer, which reflects on both faces, lights the slab's
// outside; the lightmap must hold that light, not the slab's never-lit inside (0 W/m²).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "atlas/atlas.h"
#include "bake/lightmap_bake.h"
#include "gltf_fixture.h"
#include "scene/load.h"
#include "trace/path_tracer.h"
#include "trace/rng.h"
#include "trace/sampling.h"

namespace bounce {
namespace {

// Box lo..hi as OBJ faces (1-based vertex numbers from `base`), counter-clockwise seen from
// outside when `outwards`, else from inside.
void writeBox(std::ofstream& obj, glm::vec3 lo, glm::vec3 hi, bool outwards, int base) {
  for (int i = 0; i < 8; ++i)
    obj << "v " << (i & 1 ? hi.x : lo.x) << ' ' << (i & 2 ? hi.y : lo.y) << ' '
        << (i & 4 ? hi.z : lo.z) << '\n';
  // Corners by bits (x, y, z); each quad counter-clockwise seen from outside.
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) {
    obj << 'f';
    for (int k = 0; k < 4; ++k) obj << ' ' << base + f[outwards ? k : 3 - k];
    obj << '\n';
  }
}

constexpr glm::vec3 kSlabLo{-0.4f, 0.5f, -0.05f}, kSlabHi{0.4f, 1.1f, 0.05f};

Scene roomWithAnInsideOutSlab(const test::TempDir& dir) {
  {
    std::ofstream mtl(dir / "room.mtl");
    mtl << "newmtl grey\nKd 0.7 0.7 0.7\n";
    std::ofstream obj(dir / "room.obj");
    obj << "mtllib room.mtl\ng room\nusemtl grey\n";
    writeBox(obj, glm::vec3(-1.0f, 0.0f, -1.0f), glm::vec3(1.0f, 2.0f, 1.0f), false, 1);
    obj << "g slab\nusemtl grey\n";
    writeBox(obj, kSlabLo, kSlabHi, false, 9);  // the modelling trait: wound inwards
    std::ofstream json(dir / "room.json");
    json << R"({"model": "room.obj", "lights": [{"type": "point", "name": "lamp",
               "position": [0.5, 1.7, 0.6], "intensity": [10, 10, 10]}]})";
  }
  return loadScene(dir / "room.json");
}

TEST(ClosedShellBake, InsideOutSlabGetsTheLightOfItsOutside) {
  const test::TempDir dir;
  const Scene scene = roomWithAnInsideOutSlab(dir);
  uint32_t slab = 0;
  while (slab < scene.instances.size() && scene.instances[slab].name != "slab") ++slab;
  ASSERT_LT(slab, scene.instances.size());
  const WorldGeometry geometry = flatten(scene);
  const auto kernel = makeRayKernel(geometry, RayBackend::Embree);
  AtlasSettings atlasSettings;
  atlasSettings.texelSize = 0.1f;
  const Atlas atlas = buildAtlas(scene, atlasSettings);
  LightmapBakeSettings settings = defaultBakeSettings();
  settings.irradiance.maxSpp = 512;
  settings.irradiance.targetError = 0.1f;
  settings.denoise = false;
  const LightmapBake bake = bakeLightmap(scene, geometry, *kernel, atlas.layout, settings);
  const LightmapLayout& layout = atlas.layout;
  const InstanceLightmapUv* region = layout.find(slab);
  ASSERT_NE(region, nullptr);

  // Reference: the tracer's indirect irradiance on the slab's outside (normal pointing away
  // from its centre, known from the box, not from the file's winding), at points spread by
  // area over its triangles; the lightmap read at the same points (the texel holding them).
  TraceSettings trace;
  trace.paths = PathSet::IndirectOnly;
  const PathTracer tracer(scene, geometry, *kernel, trace);
  const glm::vec3 centre = 0.5f * (kSlabLo + kSlabHi);
  uint32_t firstTriangle = 0;
  while (geometry.triangleInstance[firstTriangle] != slab) ++firstTriangle;
  const std::size_t triangles = scene.meshes[scene.instances[slab].mesh].triangleCount();
  uint32_t draws = 0;
  double sumRef = 0, sumRef2 = 0, sumBaked = 0;
  int points = 0, blackTexels = 0;
  for (std::size_t t = 0; t < triangles; ++t) {
    const glm::uvec3 tri = geometry.triangles[firstTriangle + t];
    const glm::vec3 p0 = geometry.positions[tri.x], p1 = geometry.positions[tri.y],
                    p2 = geometry.positions[tri.z];
    glm::vec3 n = glm::normalize(glm::cross(p1 - p0, p2 - p0));
    if (glm::dot(n, (p0 + p1 + p2) / 3.0f - centre) < 0.0f) n = -n;
    // Points per triangle in proportion to its area: 8 per 0.01 m².
    const float area = 0.5f * glm::length(glm::cross(p1 - p0, p2 - p0));
    for (int k = 0; k < std::max(1, static_cast<int>(area / 0.01f * 8.0f)); ++k) {
      float a = uniformFloat(11, draws++), b = uniformFloat(11, draws++);
      if (a + b > 1.0f) a = 1.0f - a, b = 1.0f - b;
      const glm::vec3 p = p0 + a * (p1 - p0) + b * (p2 - p0);
      SobolSampler sampler(5, static_cast<uint32_t>(points));
      double e = 0;
      for (int s = 0; s < 64; ++s) {
        sampler.startSample(static_cast<uint32_t>(s));
        e += luminance(tracer.irradiance(p, n, sampler)) / 64.0;
      }
      const glm::vec2 uv = region->cornerUv[3 * t] +
                           a * (region->cornerUv[3 * t + 1] - region->cornerUv[3 * t]) +
                           b * (region->cornerUv[3 * t + 2] - region->cornerUv[3 * t]);
      const int x = std::clamp(static_cast<int>(uv.x * layout.width), 0, layout.width - 1);
      const int y = std::clamp(static_cast<int>(uv.y * layout.height), 0, layout.height - 1);
      const double baked =
          luminance(bake.irradiance.pixels[static_cast<std::size_t>(y) * layout.width + x]);
      blackTexels += baked > 0.0 ? 0 : 1;
      sumRef += e, sumRef2 += e * e, sumBaked += baked;
      ++points;
    }
  }
  ASSERT_GT(points, 100);
  const double ref = sumRef / points;
  const double seRef = std::sqrt((sumRef2 / points - ref * ref) / (points - 1));
  const double baked = sumBaked / points;
  ASSERT_GT(ref, 0.0);
  EXPECT_EQ(blackTexels, 0) << "of " << points << " points on the slab read a black texel";
  // The mean over ~100 texels at a 10% target: the bake's own error is a few %; the texel
  // (10 cm) against the point where E varies smoothly adds a little more: 10% + 4 SE.
  EXPECT_NEAR(baked, ref, 0.1 * ref + 4.0 * seRef) << "reference SE " << seRef;
}

}  // namespace
}  // namespace bounce
