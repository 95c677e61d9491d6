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
#include <optional>
#include <vector>

#include "gl/shader.h"
#include "render/gpu_scene.h"
#include "render/vpl_shadow_maps.h"
#include "render/vpl_visibility_probe.h"

#include "lightmap_scenes.h"
#include "scene/load.h"
#include "shadow_scenes.h"
#include "trace/camera_render.h"
#include "vpl/vpl_gather.h"
#include "vpl/vpl_generate.h"
#include "vpl_group_visibility.h"
#include "vpl_runtime/vpl_groups.h"

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

// vplShadowCubes: every group splits into cubesPerGroup parts of its own members (halves of
// equal count ±1 along the principal axis), each cube at one of its part's VPLs; a VPL reads its
// part's cube, a tree node a cube of its own group; a group of one VPL keeps one cube.
TEST(VplShadow, SplitsEachGroupIntoPartsOfItsOwnMembers) {
  std::vector<Vpl> vpls;
  for (int i = 0; i < 1000; ++i) {
    Vpl v;
    // Two slabs far apart (the groups) stretched along x (the parts' axis) and a lone VPL.
    const float t = static_cast<float>(i % 500) / 500.0f;
    v.position = {2.0f * t, i < 500 ? 0.0f : 5.0f, 0.1f * std::sin(37.0f * t)};
    v.normal = {0.0f, 1.0f, 0.0f};
    v.flux = glm::vec3(1e-3f * (1.0f + t));
    vpls.push_back(v);
  }
  vpls.push_back(Vpl{{0.0f, -9.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, glm::vec3(1e-3f)});
  const VplGroups groups(vpls, 3);
  ASSERT_EQ(groups.groupCount(), 3u);
  for (const int perGroup : {1, 2, 4}) {
    const VplShadowCubes cubes = vplShadowCubes(groups, perGroup);
    ASSERT_EQ(cubes.cubeOf.size(), groups.lights().size());
    std::vector<std::vector<std::size_t>> members(cubes.origins.size());
    for (std::size_t i = 0; i < groups.vplCount(); ++i) members[cubes.cubeOf[i]].push_back(i);
    std::vector<std::size_t> cubesOfGroup(groups.groupCount(), 0);
    for (std::size_t c = 0; c < cubes.origins.size(); ++c) {
      ASSERT_FALSE(members[c].empty()) << "cube " << c << " reads no VPL";
      const uint32_t g = groups.groupOf(members[c][0]);
      ++cubesOfGroup[g];
      bool originIsMember = false;
      for (const std::size_t i : members[c]) {
        EXPECT_EQ(groups.groupOf(i), g) << "a part spans two groups";
        originIsMember = originIsMember || groups.lights()[i].position == cubes.origins[c].position;
      }
      EXPECT_TRUE(originIsMember) << "cube " << c << " sits at none of its VPLs";
      const std::size_t expected = groups.groups()[g].count / static_cast<std::size_t>(perGroup);
      if (groups.groups()[g].count > 1) {
        EXPECT_LE(std::max(members[c].size(), expected) - std::min(members[c].size(), expected),
                  1u);
      }
    }
    for (std::size_t g = 0; g < groups.groupCount(); ++g)
      EXPECT_EQ(cubesOfGroup[g], groups.groups()[g].count > 1 ? std::size_t(perGroup) : 1u);
    for (std::size_t light = groups.vplCount(); light < groups.lights().size(); ++light)
      EXPECT_EQ(groups.groupOf(members[cubes.cubeOf[light]][0]), groups.groupOf(light));
  }
  EXPECT_THROW(vplShadowCubes(groups, 3), std::invalid_argument);
  testContext();
  VplShadowSettings eight;
  eight.cubesPerGroup = 8;
  EXPECT_THROW(VplShadowMaps(eight, gl::shaderDirectory()), std::invalid_argument);
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

// The Cornell box with its default VPL set in 64 groups, split into parts as the renderer places
// its cubes (up to 4 per group, vplShadowCubes): the gather with each VPL weighted by its part's
// cube visibility against the same gather with exact rays from the same points, at receivers on the
// floor, the back wall and the tall block's faces. The maps may differ only at shadow edges (a
// texel's width at 64²), so the summed absolute difference stays within 3% of the summed
// irradiance; without visibility it is far larger (the test would not notice a map that saw
// nothing).
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
  maps.setRepresentatives(groups.cubes);
  maps.render(gpu);
  VplVisibilityProbe reader(gl::shaderDirectory());
  std::vector<std::vector<float>> fromMaps;
  for (std::size_t c = 0; c < groups.cubes.size(); ++c)
    fromMaps.push_back(reader.read(maps, static_cast<int>(c), positions, normals));

  double sumRays = 0.0, diffMaps = 0.0, diffNone = 0.0;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    std::vector<float> rays, mapped, none(groups.cubes.size(), 1.0f);
    for (std::size_t c = 0; c < groups.cubes.size(); ++c) {
      rays.push_back(segmentVisible(*kernel, groups.cubes[c].position, groups.cubes[c].normal,
                                    positions[i], normals[i])
                         ? 1.0f
                         : 0.0f);
      mapped.push_back(fromMaps[c][i]);
    }
    const double eRays =
        sum(glm::vec3(groupGather(groups.vpls, groups.cube, rays, positions[i], normals[i], r)));
    const double eMaps =
        sum(glm::vec3(groupGather(groups.vpls, groups.cube, mapped, positions[i], normals[i], r)));
    const double eNone =
        sum(glm::vec3(groupGather(groups.vpls, groups.cube, none, positions[i], normals[i], r)));
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
  s.bake.manifest = minimalManifest(s.scene);
  s.bake.manifest.vpls = BakeManifest::Vpls{.count = vpls.size(), .clampDistance = 0.02f};
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
  // (vpl_runtime/vpl_occlusion.h), so only the VPL shadow maps darken the floor.
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

// The light paths the dynamic box cuts (vpl_runtime/vpl_occlusion.h), through the renderer: VPLs on
// a ceiling patch whose incoming segments start at the origin, under the box, so that the box
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

namespace bounce::test {
namespace {

// One VPL group whose members see a dynamic sphere differently (render/vpl_shadow_maps.h): 64
// VPLs on a ceiling left of a hanging partition (A) and 64 right of it (B), facing down, in a
// single group (RendererSettings::vpls.groups = 1). The sphere hangs right of the partition, so
// that every segment from A to it crosses the partition 10 cm or more inside its edge and no
// segment from B comes near it: exactly, A's light never reaches the sphere and all of B's
// does. The renderer (vpl mode, no culling: every VPL evaluated) with its shadow cubes must give
// the sphere what the CPU gather with a ray per VPL gives (baker/vpl/vpl_gather.h). One cube
// for the group sits at a member next to the partition, on one side: it either lets A through
// or hides B. The split into parts along the members' principal axis puts A's and B's cubes on
// their own sides.
//
// Per sphere pixel: A's cubes read 0 (deep umbra, at least 10 cm of partition) and B's cubes
// whose origin p faces by more than the maps' uncertainty (3 texels at 64², the margin of
// `classify`) read ≥ 0.99 (the lit bound of the tests above). A cube whose origin p does not
// face that clearly may see the sphere's own far side in front of p (a convex receiver never
// occludes a VPL it faces, but a cube at another point than the VPL can see its back) and read
// 0. So |L_maps − L_rays| ≤ ρ/π·E_rays(VPLs of such cubes) + 0.01·L_noV plus the float rounding
// of VplRender (1e-4 relative) and what L changes by over the rasterizer's sub-pixel step (a real
// GPU's interpolated point is not the ray's exactly: NVIDIA's differs by 2-5e-4 of L here); at
// least 100 pixels face every origin (the first term 0).
TEST(VplShadow, EachVplOfAGroupReadsTheCubeOfItsOwnPart) {
  testContext();
  Scene scene;
  addBox(scene, {-0.01f, 0.3f, -0.6f}, {0.01f, 1.05f, 0.6f}, grey("partition"));
  Material white = grey("sphere");
  white.albedo = glm::vec3(0.8f);
  const glm::vec3 centre(0.3f, 0.2f, 0.0f);
  const uint32_t sphere =
      addInstance(scene, uvSphere(0.1f, 24, 48), white, glm::translate(glm::mat4(1.0f), centre));
  scene.instances[sphere].mobility = Mobility::Dynamic;
  std::vector<Vpl> vpls;
  for (int side = 0; side < 2; ++side)
    for (int i = 0; i < 64; ++i) {
      Vpl v;
      const float x = 0.1f + 0.4f * static_cast<float>(i % 8) / 7.0f;
      v.position = {side == 0 ? -x : x, 1.0f, -0.2f + 0.4f * static_cast<float>(i / 8) / 7.0f};
      v.normal = {0.0f, -1.0f, 0.0f};
      v.flux = side == 0 ? glm::vec3(2e-3f, 1e-3f, 5e-4f) : glm::vec3(5e-4f, 1e-3f, 2e-3f);
      v.from = v.position + glm::vec3(0.0f, 0.5f, 0.0f);  // from above: the sphere cuts no path
      v.path = static_cast<uint32_t>(vpls.size());
      vpls.push_back(v);
    }
  Bake bake;
  bake.layout.width = bake.layout.height = 1;
  bake.layout.texelSize = 1.0f;
  bake.irradiance = Image(1, 1);
  bake.manifest = minimalManifest(scene);
  constexpr float kClamp = 0.02f;  // m; every VPL is ≥ 0.6 m from the sphere
  bake.manifest.vpls = BakeManifest::Vpls{.count = vpls.size(), .clampDistance = kClamp};
  bake.vpls = vpls;
  RendererSettings settings;
  settings.mode = RenderMode::Vpl;
  settings.vpls.groups = 1;
  settings.vpls.culling = false;
  ForwardRenderer on(scene, gl::shaderDirectory(), settings, &bake);
  settings.vpls.shadows.enabled = false;
  ForwardRenderer off(scene, gl::shaderDirectory(), settings, &bake);

  Camera camera;
  const glm::vec3 eye(0.3f, 0.5f, -0.6f);
  camera.cameraToWorld = glm::inverse(glm::lookAt(eye, centre, glm::vec3(0, 1, 0)));
  camera.yfov = 2.0f * std::asin(1.05f * 0.1f / glm::length(centre - eye));
  constexpr int kSize = 24;
  const Image withMaps = on.renderImage(camera, kSize, kSize);
  const Image without = off.renderImage(camera, kSize, kSize);

  // Each input VPL's cube origin (the renderer's arrangement; VplGroups reorders the VPLs).
  const VplGroups group(vpls, 1);
  const VplShadowCubes cubes = vplShadowCubes(group, VplShadowSettings{}.cubesPerGroup);
  std::vector<glm::vec3> originOf(vpls.size());
  for (std::size_t i = 0; i < group.vplCount(); ++i)
    originOf[group.vplOrder()[i]] = cubes.origins[cubes.cubeOf[i]].position;
  const WorldGeometry geometry = flatten(scene);
  const auto kernel = makeRayKernel(geometry, RayBackend::Embree);
  const float margin = std::sin(3.0f * 2.0f / 64.0f);  // 3 texels at 64², as `classify`
  const glm::dvec3 rhoPi = glm::dvec3(white.albedo) / 3.14159265358979;
  int pixels = 0, certain = 0;
  double sumRays = 0.0, sumNone = 0.0, sumError = 0.0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      // The sphere point a raster point (px, py) sees: position, interpolated and geometric
      // normal.
      struct SpherePoint {
        glm::vec3 p, n, ng;
      };
      const auto sphereAt = [&](float px, float py) -> std::optional<SpherePoint> {
        const Hit hit = kernel->intersect(cameraRay(camera, kSize, kSize, px, py));
        if (!hit.valid() || geometry.triangleInstance[hit.triangle] != sphere) return std::nullopt;
        const glm::uvec3 t = geometry.triangles[hit.triangle];
        const Ray ray = cameraRay(camera, kSize, kSize, px, py);
        return SpherePoint{
            ray.origin + hit.t * ray.direction,
            glm::normalize((1 - hit.u - hit.v) * geometry.normals[t.x] +
                           hit.u * geometry.normals[t.y] + hit.v * geometry.normals[t.z]),
            glm::normalize(glm::cross(geometry.positions[t.y] - geometry.positions[t.x],
                                      geometry.positions[t.z] - geometry.positions[t.x]))};
      };
      const std::optional<SpherePoint> seen =
          sphereAt(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
      if (!seen) continue;
      const glm::vec3 p = seen->p, n = seen->n, ng = seen->ng;
      // The VPLs whose cube origin p does not face by the margin: that cube may see the
      // sphere's own far side in front of p (or p within the maps' uncertainty of its own
      // horizon) and shadow p from a VPL that does light it.
      std::vector<Vpl> uncertain;
      for (std::size_t v = 0; v < vpls.size(); ++v)
        if (glm::dot(ng, glm::normalize(originOf[v] - p)) <= margin) uncertain.push_back(vpls[v]);
      const std::size_t i = static_cast<std::size_t>(y) * kSize + x;
      const glm::dvec3 rays =
          rhoPi * gatherVplIrradiance(vpls, p, n, kernel.get(), kClamp).irradiance;
      const glm::dvec3 none = rhoPi * gatherVplIrradiance(vpls, p, n, nullptr, kClamp).irradiance;
      const glm::dvec3 selfShadow =
          rhoPi * gatherVplIrradiance(uncertain, p, n, kernel.get(), kClamp).irradiance;
      // What the unshadowed light changes by over the rasterizer's sub-pixel step (a sample
      // off the sphere counts as all of it).
      glm::dvec3 spread(0.0);
      for (const glm::vec2 o : subpixelOffsets(testContext())) {
        const std::optional<SpherePoint> q =
            sphereAt(static_cast<float>(x) + 0.5f + o.x, static_cast<float>(y) + 0.5f + o.y);
        spread = glm::max(
            spread,
            q ? glm::abs(rhoPi * gatherVplIrradiance(vpls, q->p, q->n, nullptr, kClamp).irradiance -
                         none)
              : none);
      }
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(without.pixels[i][c], none[c], 1e-4 * none[c] + 1e-9 + spread[c])
            << "no VPL shadows, pixel (" << x << ", " << y << ") channel " << c
            << " (sub-pixel spread " << spread[c] << ")";
        EXPECT_NEAR(withMaps.pixels[i][c], rays[c],
                    selfShadow[c] + 0.01 * none[c] + 1e-4 * rays[c] + 1e-9 + spread[c])
            << "pixel (" << x << ", " << y << ") channel " << c << ": without visibility "
            << none[c] << ", from VPLs whose cube p does not face " << selfShadow[c];
        sumError += std::abs(withMaps.pixels[i][c] - rays[c]);
      }
      sumRays += rays.r + rays.g + rays.b, sumNone += none.r + none.g + none.b;
      ++pixels;
      certain += uncertain.empty() ? 1 : 0;
    }
  std::printf(
      "%d sphere pixels (%d facing every cube origin); exact visibility keeps %.3f of the VPL "
      "light; sum |L_maps - L_rays| / sum L_rays = %.4f\n",
      pixels, certain, sumRays / sumNone, sumError / sumRays);
  EXPECT_GE(certain, 100);
  // A's light is a real part of the sphere's (the test would not see a cube that let it in).
  EXPECT_LE(sumRays, 0.8 * sumNone);
  EXPECT_GE(sumRays, 0.2 * sumNone);
}

// What fits the driver's array layers (6 per cube): llvmpipe's 2048 take 64 groups × 4 cubes;
// 1024 halve the cubes; GL 3.3's minimum of 256 leaves one cube for each of 42 groups; under 6,
// none. For every layer count the budget fits, and no larger cube count would.
TEST(VplShadow, BudgetFitsTheDriversArrayLayers) {
  const auto budget = [](int layers) { return vplShadowBudget(layers, kMaxVplShadowGroups, 4); };
  EXPECT_EQ(budget(2048).groups, 64);
  EXPECT_EQ(budget(2048).cubesPerGroup, 4);
  EXPECT_EQ(budget(1024).groups, 64);
  EXPECT_EQ(budget(1024).cubesPerGroup, 2);
  EXPECT_EQ(budget(256).groups, 42);
  EXPECT_EQ(budget(256).cubesPerGroup, 1);
  EXPECT_EQ(budget(5).groups, 0);
  for (int layers = 0; layers <= 3000; ++layers) {
    const VplShadowBudget b = budget(layers);
    ASSERT_LE(6 * b.groups * b.cubesPerGroup, layers) << layers;
    if (b.cubesPerGroup < 4) {
      ASSERT_GT(6 * kMaxVplShadowGroups * 2 * b.cubesPerGroup, layers) << layers;
    }
  }
}

}  // namespace
}  // namespace bounce::test
