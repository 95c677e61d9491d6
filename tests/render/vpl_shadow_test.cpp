// VPL shadow maps (engine/render/vpl_shadow_maps.h, shaders/vpl_shadows.glsl): vplVisibility
// read back at chosen receivers through shaders/vpl_visibility_probe.frag, against exact
// visibility from the baker's ray kernel. A receiver counts as "deep umbra" when it and its
// neighbours a margin away on its surface are all occluded, "well outside" when none are; the
// margin is the map's uncertainty there: 3 texels at the receiver's distance (bilinear
// footprint 1, normal offset 1.5, rounding) plus the origin offset, spread on the surface by
// 1/cosθ_x. Between the two the map may filter; elsewhere it must agree.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <nlohmann/json.hpp>
#include "gl/shader.h"
#include "render/gpu_scene.h"
#include "render/vpl_shadow_maps.h"
#include "render/vpl_visibility_probe.h"

#include "lightmap_scenes.h"
#include "scene/load.h"
#include "shadow_scenes.h"
#include "vpl/vpl_gather.h"
#include "vpl/vpl_generate.h"
#include "vpl_group_visibility.h"

namespace bounce::test {
namespace {

struct Receiver {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f};  // unit, facing the VPL's side
  glm::vec3 tangent{0.0f}, bitangent{0.0f};
  glm::vec3 lo{0.0f}, hi{0.0f};  // the surface's extent (neighbours are clamped into it)
};

// vplVisibility of group `group` at each receiver, read through the probe shader.
std::vector<float> probe(const VplShadowMaps& maps, int group,
                         const std::vector<Receiver>& receivers) {
  std::vector<glm::vec3> positions, normals;
  for (const Receiver& r : receivers) {
    positions.push_back(r.position);
    normals.push_back(r.normal);
  }
  VplVisibilityProbe reader(gl::shaderDirectory());
  return reader.read(maps, group, positions, normals);
}

bool occluded(const RayKernel& kernel, const Vpl& vpl, glm::vec3 p, glm::vec3 np) {
  const glm::vec3 from = offsetRayOrigin(vpl.position, vpl.normal, p - vpl.position);
  const glm::vec3 to = offsetRayOrigin(p, np, vpl.position - p);
  Ray ray;
  ray.origin = from;
  ray.direction = to - from;
  ray.tmax = 1.0f;
  return kernel.occluded(ray);
}

// Receivers on the axis-aligned rectangle [lo, hi] (one extent zero) with normal n, `count`
// per side.
void addGrid(std::vector<Receiver>& out, glm::vec3 lo, glm::vec3 hi, glm::vec3 n, int count) {
  glm::vec3 t(0.0f), b(0.0f);
  int axis = 0;
  for (int i = 0; i < 3; ++i)
    if (hi[i] == lo[i]) axis = i;
  t[(axis + 1) % 3] = 1.0f;
  b[(axis + 2) % 3] = 1.0f;
  for (int i = 0; i < count; ++i)
    for (int j = 0; j < count; ++j) {
      const float s = (static_cast<float>(i) + 0.5f) / static_cast<float>(count);
      const float r = (static_cast<float>(j) + 0.5f) / static_cast<float>(count);
      glm::vec3 p = lo;
      p[(axis + 1) % 3] = glm::mix(lo[(axis + 1) % 3], hi[(axis + 1) % 3], s);
      p[(axis + 2) % 3] = glm::mix(lo[(axis + 2) % 3], hi[(axis + 2) % 3], r);
      out.push_back({p, n, t, b, lo, hi});
    }
}

struct Classified {
  int umbra = 0, outside = 0;
  int umbraWrong = 0, outsideWrong = 0;  // umbra with V > 0.01, outside with V < 0.99
  float worstOutside = 1.0f, worstUmbra = 0.0f;
};

Classified classify(const RayKernel& kernel, const Vpl& vpl, float originOffset, int resolution,
                    const std::vector<Receiver>& receivers, const std::vector<float>& visibility) {
  Classified c;
  for (std::size_t i = 0; i < receivers.size(); ++i) {
    const Receiver& r = receivers[i];
    const glm::vec3 toVpl = vpl.position - r.position;
    const float d = glm::length(toVpl);
    const float cosX = glm::dot(r.normal, toVpl) / d;
    const float cosY = -glm::dot(vpl.normal, toVpl) / d;
    if (cosX <= 0.0f || cosY <= 0.0f) continue;  // the VPL does not light it
    const float margin =
        (3.0f * 2.0f / static_cast<float>(resolution) * d + originOffset) / std::max(cosX, 0.1f);
    int hidden = 0, tested = 0;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const glm::vec3 q = glm::clamp(r.position + margin * (static_cast<float>(dx) * r.tangent +
                                                              static_cast<float>(dy) * r.bitangent),
                                       r.lo, r.hi);
        hidden += occluded(kernel, vpl, q, r.normal) ? 1 : 0;
        ++tested;
      }
    if (hidden == tested) {
      ++c.umbra;
      c.worstUmbra = std::max(c.worstUmbra, visibility[i]);
      if (visibility[i] > 0.01f) ++c.umbraWrong;
    } else if (hidden == 0) {
      ++c.outside;
      c.worstOutside = std::min(c.worstOutside, visibility[i]);
      if (visibility[i] < 0.99f) ++c.outsideWrong;
    }
  }
  return c;
}

Material grey(const char* name) {
  Material m;
  m.name = name;
  m.albedo = glm::vec3(0.5f);
  m.doubleSided = true;
  return m;
}

// A 3 m × 2.4 m × 3 m room, a tilted plate the VPL sits on, an occluding box above it.
struct Room {
  Scene scene;
  Vpl vpl;
  std::vector<Receiver> receivers;
};

Room roomWithOccluder() {
  Room room;
  addBox(room.scene, {-1.5f, 0.0f, -1.5f}, {1.5f, 2.4f, 1.5f}, grey("room"));
  room.vpl.normal = glm::normalize(glm::vec3(0.4f, 1.0f, -0.3f));
  room.vpl.position = {-0.2f, 0.8f, 0.1f};
  room.vpl.flux = glm::vec3(1.0f);
  // The plate through the VPL, perpendicular to its normal, 30 cm across.
  const glm::vec3 u = 0.3f * glm::normalize(glm::cross(room.vpl.normal, glm::vec3(0, 0, 1)));
  const glm::vec3 v = 0.3f * glm::normalize(glm::cross(room.vpl.normal, u));
  addQuad(room.scene, room.vpl.position - 0.5f * (u + v), u, v, grey("plate"));
  addBox(room.scene, {0.1f, 1.3f, -0.5f}, {0.6f, 1.5f, 0.0f}, grey("occluder"));
  const int n = 40;
  addGrid(room.receivers, {-1.5f, 2.4f, -1.5f}, {1.5f, 2.4f, 1.5f}, {0, -1, 0}, n);  // ceiling
  addGrid(room.receivers, {1.5f, 0.0f, -1.5f}, {1.5f, 2.4f, 1.5f}, {-1, 0, 0}, n);   // +x wall
  addGrid(room.receivers, {-1.5f, 0.0f, -1.5f}, {-1.5f, 2.4f, 1.5f}, {1, 0, 0}, n);  // −x wall
  addGrid(room.receivers, {-1.5f, 0.0f, -1.5f}, {1.5f, 2.4f, -1.5f}, {0, 0, 1}, n);  // −z wall
  addGrid(room.receivers, {-1.5f, 0.0f, 1.5f}, {1.5f, 2.4f, 1.5f}, {0, 0, -1}, n);   // +z wall
  addGrid(room.receivers, {-1.5f, 0.0f, -1.5f}, {1.5f, 0.0f, 1.5f}, {0, 1, 0}, n);   // floor
  // The occluder's own faces that see the VPL (contact with its caster's map).
  addGrid(room.receivers, {0.1f, 1.3f, -0.5f}, {0.6f, 1.3f, 0.0f}, {0, -1, 0}, 12);
  addGrid(room.receivers, {0.1f, 1.3f, -0.5f}, {0.1f, 1.5f, 0.0f}, {-1, 0, 0}, 12);
  return room;
}

TEST(VplShadow, SkipsOnlyTheFacesBehindTheVpl) {
  EXPECT_EQ(vplShadowFaces({0, 1, 0}), 0b110111u);   // −Y skipped
  EXPECT_EQ(vplShadowFaces({-1, 0, 0}), 0b111110u);  // +X skipped
  // Tilted 25° from +y, −Y's whole cone still lies behind it; along a diagonal every face
  // has a corner in front.
  EXPECT_EQ(vplShadowFaces(glm::normalize(glm::vec3(0.4f, 1.0f, -0.3f))), 0b110111u);
  EXPECT_EQ(vplShadowFaces(glm::normalize(glm::vec3(1.0f, 1.0f, 1.0f))), 0b111111u);
}

// The umbra of the box is 0 and every lit receiver (walls, ceiling, floor, the occluder's own
// lit faces, grazing and head-on) is ≥ 0.99: right faces, no acne, no light leaks.
TEST(VplShadow, UmbraAndLitSurfacesAgreeWithRayTracing) {
  testContext();
  const Room room = roomWithOccluder();
  std::vector<std::string> warnings;
  const GpuScene gpu(room.scene, warnings);
  VplShadowMaps maps(VplShadowSettings{}, gl::shaderDirectory());
  maps.setRepresentatives(std::span<const Vpl>(&room.vpl, 1));
  EXPECT_EQ(maps.render(gpu).views, 5);  // −Y lies behind the VPL
  const std::vector<float> visibility = probe(maps, 0, room.receivers);
  const auto kernel = makeRayKernel(flatten(room.scene), RayBackend::Embree);
  const Classified c =
      classify(*kernel, room.vpl, maps.originOffset(), 64, room.receivers, visibility);
  std::printf("umbra %d (wrong %d, worst %.4f), well outside %d (wrong %d, worst %.4f)\n", c.umbra,
              c.umbraWrong, c.worstUmbra, c.outside, c.outsideWrong, c.worstOutside);
  EXPECT_GE(c.umbra, 100);
  EXPECT_GE(c.outside, 3000);
  EXPECT_EQ(c.umbraWrong, 0) << "worst umbra visibility " << c.worstUmbra;
  EXPECT_EQ(c.outsideWrong, 0) << "worst lit visibility " << c.worstOutside;

  // Off: visibility 1 everywhere, nothing drawn.
  maps.setEnabled(false);
  EXPECT_EQ(maps.render(gpu).views, 0);
  for (const float v : probe(maps, 0, room.receivers)) ASSERT_EQ(v, 1.0f);
}

// A VPL on the floor 1.5 cm from a wall: the wall right next to it (down to 2 mm, inside the
// clamp radius) and the ceiling see it; nothing may self-shadow at the concave corner, also
// when the VPL lies 10 µm under its floor (a baked hit point's rounding at a scale of ~100 m)
// or 1 mm under it (less than the origin offset, 1e-3 × the 3.5 m diagonal).
TEST(VplShadow, NoSelfShadowAtAConcaveCorner) {
  testContext();
  Scene scene;
  addBox(scene, {-1.0f, 0.0f, -1.0f}, {1.0f, 2.0f, 1.0f}, grey("room"));
  std::vector<Receiver> receivers;
  const glm::vec3 wallN(-1, 0, 0), t(0, 1, 0), b(0, 0, 1);
  for (const float h : {0.002f, 0.005f, 0.01f, 0.02f, 0.05f, 0.1f, 0.3f, 0.7f, 1.5f})
    for (const float z : {-0.6f, -0.1f, -0.01f, 0.0f, 0.004f, 0.03f, 0.2f, 0.8f})
      receivers.push_back({{1.0f, h, z}, wallN, t, b, {1, 0, -1}, {1, 2, 1}});
  addGrid(receivers, {-1.0f, 2.0f, -1.0f}, {1.0f, 2.0f, 1.0f}, {0, -1, 0}, 20);
  addGrid(receivers, {-1.0f, 0.0f, -1.0f}, {-1.0f, 2.0f, 1.0f}, {1, 0, 0}, 20);
  std::vector<std::string> warnings;
  const GpuScene gpu(scene, warnings);
  for (const float y : {0.0f, -1e-5f, -1e-3f}) {
    Vpl vpl;
    vpl.position = {0.985f, y, 0.0f};
    vpl.normal = {0.0f, 1.0f, 0.0f};
    vpl.flux = glm::vec3(1.0f);
    VplShadowMaps maps(VplShadowSettings{}, gl::shaderDirectory());
    maps.setRepresentatives(std::span<const Vpl>(&vpl, 1));
    EXPECT_EQ(maps.render(gpu).views, 5);  // the face under the floor is skipped
    const std::vector<float> visibility = probe(maps, 0, receivers);
    int wrong = 0;
    for (std::size_t i = 0; i < receivers.size(); ++i) {
      if (visibility[i] >= 0.99f) continue;
      if (++wrong <= 5)
        ADD_FAILURE() << "VPL at y = " << y << ": visibility " << visibility[i] << " at "
                      << receivers[i].position.x << ", " << receivers[i].position.y << ", "
                      << receivers[i].position.z;
    }
    EXPECT_EQ(wrong, 0) << "of " << receivers.size() << " receivers, VPL at y = " << y;
  }
}

// VPLs over an open floor, near it and far, facing along it or tilted down towards it: every
// floor point in front of the VPL is lit (≥ 0.99). A lookup pushed towards the VPL's normal
// near its horizon (an earlier bias) shadowed a third of this floor.
TEST(VplShadow, NoSelfShadowOnAnOpenFloor) {
  testContext();
  Scene scene;
  addQuad(scene, {-0.5f, 0, 0.5f}, {1, 0, 0}, {0, 0, -1}, grey("floor"));
  std::vector<std::string> warnings;
  const GpuScene gpu(scene, warnings);
  std::vector<Receiver> floor;
  addGrid(floor, {-0.5f, 0.0f, -0.5f}, {0.5f, 0.0f, 0.5f}, {0, 1, 0}, 50);
  const glm::vec3 tilted = glm::normalize(glm::vec3(0.0f, -std::cos(0.52f), std::sin(0.52f)));
  for (const glm::vec3 n : {glm::vec3(1, 0, 0), tilted})
    for (const float h : {0.002f, 0.02f, 0.3f}) {
      Vpl vpl;
      vpl.position = {n.x > 0.5f ? -0.45f : 0.0f, h, 0.0f};
      vpl.normal = n;
      VplShadowMaps maps(VplShadowSettings{}, gl::shaderDirectory());
      maps.setRepresentatives(std::span<const Vpl>(&vpl, 1));
      maps.render(gpu);
      const std::vector<float> visibility = probe(maps, 0, floor);
      int wrong = 0, lit = 0;
      for (std::size_t i = 0; i < floor.size(); ++i) {
        if (glm::dot(floor[i].position - vpl.position, n) <= 0.0f) continue;
        ++lit;
        if (visibility[i] < 0.99f) ++wrong;
      }
      EXPECT_GT(lit, 500);
      EXPECT_EQ(wrong, 0) << "of " << lit << " floor receivers, VPL normal (" << n.x << ", " << n.y
                          << ", " << n.z << ") at height " << h;
    }
}

// Maps are redrawn only when something they depend on changed.
TEST(VplShadow, RedrawsOnlyWhenVplsOrCastersMove) {
  testContext();
  Room room = roomWithOccluder();
  room.scene.instances.back().mobility = Mobility::Dynamic;
  std::vector<std::string> warnings;
  GpuScene gpu(room.scene, warnings);
  VplShadowMaps maps(VplShadowSettings{}, gl::shaderDirectory());
  maps.setRepresentatives(std::span<const Vpl>(&room.vpl, 1));
  EXPECT_GT(maps.render(gpu).views, 0);
  EXPECT_EQ(maps.render(gpu).views, 0);
  maps.setRepresentatives(std::span<const Vpl>(&room.vpl, 1));
  EXPECT_EQ(maps.render(gpu).views, 0);
  const std::size_t occluder = room.scene.instances.size() - 1;
  gpu.setInstanceTransform(occluder, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 0.8f)));
  EXPECT_GT(maps.render(gpu).views, 0);
  EXPECT_EQ(maps.render(gpu).views, 0);
  Vpl moved = room.vpl;
  moved.position.x += 0.1f;
  maps.setRepresentatives(std::span<const Vpl>(&moved, 1));
  EXPECT_GT(maps.render(gpu).views, 0);

  // The box moved 0.8 m along +z: the receivers now agree with the moved geometry.
  Scene movedScene = room.scene;
  movedScene.instances.back().transform =
      glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 0.8f));
  const std::vector<float> visibility = probe(maps, 0, room.receivers);
  const auto kernel = makeRayKernel(flatten(movedScene), RayBackend::Embree);
  const Classified c =
      classify(*kernel, moved, maps.originOffset(), 64, room.receivers, visibility);
  EXPECT_GE(c.umbra, 100);
  EXPECT_EQ(c.umbraWrong, 0) << "worst umbra visibility " << c.worstUmbra;
  EXPECT_EQ(c.outsideWrong, 0) << "worst lit visibility " << c.worstOutside;
}

// The Cornell box with its default VPL set in 64 groups, each group's cube at its member nearest
// the centroid: the group-visibility gather with the maps' visibility against the same gather
// with exact rays from the same points, at receivers on the floor, the back wall and the tall
// block's faces. The maps may differ only at shadow edges (a texel's width at 64²), so the
// summed absolute difference stays within 3% of the summed irradiance; without visibility it
// is far larger (the test would not notice a map that saw nothing).
TEST(VplShadow, CornellMapsMatchRaysFromTheSamePoints) {
  testContext();
  const Scene scene =
      loadScene(std::filesystem::path(BOUNCE_SOURCE_DIR) / "content/cornell_box/cornell_box.gltf");
  const WorldGeometry geometry = flatten(scene);
  const auto kernel = makeRayKernel(geometry, RayBackend::Embree);
  const std::vector<Vpl> vpls = generateVpls(scene, geometry, *kernel, VplSettings{}).vpls;
  ASSERT_GT(vpls.size(), 1000u);
  const float r = vplClampDistance(surfaceArea(geometry), vpls.size());
  const VplGroupsCpu groups = groupVplsCpu(vpls, kMaxVplShadowGroups);

  std::vector<glm::vec3> positions, normals;
  for (float a = 0.02f; a < 0.55f; a += 0.04f)
    for (float b = 0.02f; b < 0.55f; b += 0.04f) {
      positions.emplace_back(a, 0.0f, b);  // floor (some points under the blocks: E = 0 both ways)
      normals.emplace_back(0.0f, 1.0f, 0.0f);
      positions.emplace_back(a, b, 0.5585f);  // back wall
      normals.emplace_back(0.0f, 0.0f, -1.0f);
    }
  std::vector<std::string> warnings;
  const GpuScene gpu(scene, warnings);
  VplShadowMaps maps(VplShadowSettings{}, gl::shaderDirectory());
  maps.setRepresentatives(groups.origins);
  maps.render(gpu);
  VplVisibilityProbe reader(gl::shaderDirectory());
  std::vector<std::vector<float>> fromMaps;
  for (std::size_t g = 0; g < groups.origins.size(); ++g)
    fromMaps.push_back(reader.read(maps, static_cast<int>(g), positions, normals));

  double sumRays = 0.0, diffMaps = 0.0, diffNone = 0.0;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    std::vector<float> rays, mapped, none(groups.origins.size(), 1.0f);
    for (std::size_t g = 0; g < groups.origins.size(); ++g) {
      rays.push_back(segmentVisible(*kernel, groups.origins[g].position, groups.origins[g].normal,
                                    positions[i], normals[i])
                         ? 1.0f
                         : 0.0f);
      mapped.push_back(fromMaps[g][i]);
    }
    const double eRays =
        sum(glm::vec3(groupGather(groups.vpls, groups.group, rays, positions[i], normals[i], r)));
    const double eMaps =
        sum(glm::vec3(groupGather(groups.vpls, groups.group, mapped, positions[i], normals[i], r)));
    const double eNone =
        sum(glm::vec3(groupGather(groups.vpls, groups.group, none, positions[i], normals[i], r)));
    sumRays += eRays;
    diffMaps += std::abs(eMaps - eRays);
    diffNone += std::abs(eNone - eRays);
  }
  std::printf("Σ|E_maps − E_rays| / ΣE_rays = %.4f, without visibility %.4f\n", diffMaps / sumRays,
              diffNone / sumRays);
  EXPECT_LE(diffMaps, 0.03 * sumRays);
  EXPECT_GE(diffNone, 0.15 * sumRays);
}

// The renderer tests' scene: a 1 m floor (y = 0) with a dynamic 20 cm box on it, and a bake
// of 64 VPLs (1 mW each, facing down) on an 8 × 8 patch 0.4 m up, over the box, each its own
// light path whose incoming segment starts at from(VPL position).
struct BoxUnderVpls {
  Scene scene;
  std::size_t box = 0;  // the box's instance
  Bake bake;
};

BoxUnderVpls boxUnderVpls(glm::vec3 (*from)(glm::vec3 position)) {
  BoxUnderVpls s;
  addQuad(s.scene, {-0.5f, 0, 0.5f}, {1, 0, 0}, {0, 0, -1}, grey("floor"));
  addBox(s.scene, {0.0f, 0.15f, -0.1f}, {0.2f, 0.2f, 0.1f}, grey("box"));
  s.box = s.scene.instances.size() - 1;
  s.scene.instances[s.box].mobility = Mobility::Dynamic;
  s.bake.layout.width = s.bake.layout.height = 1;
  s.bake.layout.texelSize = 1.0f;
  s.bake.irradiance = Image(1, 1);
  std::vector<Vpl> vpls;
  for (int i = 0; i < 64; ++i) {
    Vpl v;
    v.position = {0.2f + 0.02f * static_cast<float>(i % 8), 0.4f,
                  -0.07f + 0.02f * static_cast<float>(i / 8)};
    v.normal = {0.0f, -1.0f, 0.0f};
    v.flux = glm::vec3(1e-3f);
    v.from = from(v.position);
    v.path = static_cast<uint32_t>(i);
    vpls.push_back(v);
  }
  nlohmann::json manifest = nlohmann::json::parse(minimalManifest(s.scene));
  manifest["vpls"] = {{"count", vpls.size()}, {"clampDistance", 0.02f}};
  s.bake.manifestJson = manifest.dump();
  s.bake.vpls = vpls;
  return s;
}

// The renderer end to end (vpl mode): VPLs on a ceiling patch over a floor, a dynamic box
// between. The box's shadow darkens the floor; moved out of the room, the frame equals the
// frame without VPL shadows (the cubes were redrawn, nothing shadows); moved back, the first
// frame returns exactly.
TEST(VplShadow, RendererRedrawsTheCubesWhenADynamicOccluderMoves) {
  testContext();
  // Each VPL its own path, arriving from above the ceiling patch: the box cuts none of them
  // (bake/vpl_occlusion.h), so only the VPL shadow maps darken the floor.
  const BoxUnderVpls s =
      boxUnderVpls([](glm::vec3 position) { return position + glm::vec3(0.0f, 0.5f, 0.0f); });
  const Scene& scene = s.scene;
  const std::size_t box = s.box;
  const Bake& bake = s.bake;
  RendererSettings settings;
  settings.mode = RenderMode::Vpl;
  ForwardRenderer renderer(scene, gl::shaderDirectory(), settings, &bake);
  // The reference frames come from a second renderer without VPL shadows, so that nothing but
  // the box's move can make the first one redraw its cubes.
  settings.vpls.shadows.enabled = false;
  ForwardRenderer reference(scene, gl::shaderDirectory(), settings, &bake);
  const Camera camera = downCamera(1.0f);
  constexpr int kSize = 32;
  const Image shadowed = renderer.renderImage(camera, kSize, kSize);
  const Image unshadowed = reference.renderImage(camera, kSize, kSize);
  // Floor pixels (not the box's own) darkened to below half by the box: its shadow is there.
  int dark = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const std::size_t i = shadowed.index(x, y);
      if (shadowed.pixels[i].g < 0.5f * unshadowed.pixels[i].g) ++dark;
    }
  EXPECT_GE(dark, 10);

  const glm::mat4 away = glm::translate(glm::mat4(1.0f), glm::vec3(5.0f, 0.0f, 0.0f));
  renderer.setInstanceTransform(box, away);
  reference.setInstanceTransform(box, away);
  const Image movedAway = renderer.renderImage(camera, kSize, kSize);
  const Image movedAwayUnshadowed = reference.renderImage(camera, kSize, kSize);
  for (std::size_t i = 0; i < movedAway.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(movedAway.pixels[i][c], movedAwayUnshadowed.pixels[i][c],
                  1e-4f * movedAwayUnshadowed.pixels[i][c] + 1e-9f)
          << "pixel " << i << ": the box left, its VPL shadow stayed";

  renderer.setInstanceTransform(box, glm::mat4(1.0f));
  const Image back = renderer.renderImage(camera, kSize, kSize);
  for (std::size_t i = 0; i < back.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c)
      ASSERT_EQ(back.pixels[i][c], shadowed.pixels[i][c]) << "pixel " << i;
}

// The light paths the dynamic box cuts (bake/vpl_occlusion.h), through the renderer: VPLs on a
// ceiling patch whose incoming segments start at the origin, under the box, so that the box
// blocks them. Without VPL shadows the frame is darker with the box in place; moved away
// (setInstanceTransform), it equals the frame of a renderer built with the box already away;
// moved back, the first frame returns exactly.
TEST(VplShadow, RendererCutsTheVplPathsADynamicObjectBlocksWhereverItIsMoved) {
  testContext();
  const BoxUnderVpls s = boxUnderVpls([](glm::vec3) { return glm::vec3(0.0f, 0.01f, -0.1f); });
  const Scene& scene = s.scene;
  const std::size_t box = s.box;
  const Bake& bake = s.bake;
  RendererSettings settings;
  settings.mode = RenderMode::Vpl;
  settings.vpls.shadows.enabled = false;
  ForwardRenderer renderer(scene, gl::shaderDirectory(), settings, &bake);
  const glm::mat4 away = glm::translate(glm::mat4(1.0f), glm::vec3(5.0f, 0.0f, 0.0f));
  Scene movedScene = scene;
  movedScene.instances[box].transform = away;
  ForwardRenderer moved(movedScene, gl::shaderDirectory(), settings, &bake);
  const Camera camera = downCamera(1.0f);
  constexpr int kSize = 32;
  const auto total = [](const Image& image) {
    double sum = 0.0;
    for (const glm::vec3& p : image.pixels) sum += static_cast<double>(p.g);
    return sum;
  };
  const Image cut = renderer.renderImage(camera, kSize, kSize);
  const Image open = moved.renderImage(camera, kSize, kSize);
  EXPECT_LT(total(cut), 0.5 * total(open)) << "the box cut no VPL path";

  renderer.setInstanceTransform(box, away);
  const Image movedAway = renderer.renderImage(camera, kSize, kSize);
  for (std::size_t i = 0; i < movedAway.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(movedAway.pixels[i][c], open.pixels[i][c], 1e-5f * open.pixels[i][c] + 1e-9f)
          << "pixel " << i << ": the box left, its cut stayed";
  renderer.setInstanceTransform(box, glm::mat4(1.0f));
  const Image back = renderer.renderImage(camera, kSize, kSize);
  for (std::size_t i = 0; i < back.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) ASSERT_EQ(back.pixels[i][c], cut.pixels[i][c]) << "pixel " << i;
}

}  // namespace
}  // namespace bounce::test
