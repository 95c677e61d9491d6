// orientClosedShells: a closed surface is turned to face the side its light sources are on,
// and nothing else changes.
#include <gtest/gtest.h>

#include <tbb/task_arena.h>
#include <glm/gtc/matrix_transform.hpp>

#include "scene/closed_shells.h"
#include "scene/world_geometry.h"

namespace bounce {
namespace {

// A box from lo to hi as 6 faces of 4 vertices each (flat normals, as the OBJ loader gives
// them), wound outwards or inwards, appended to `mesh`.
void addBox(Mesh& mesh, glm::vec3 lo, glm::vec3 hi, bool outwards) {
  const glm::vec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z},
                          {lo.x, hi.y, lo.z}, {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z},
                          {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
  // Counter-clockwise seen from outside.
  const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                           {3, 7, 6, 2}, {0, 4, 7, 3}, {1, 2, 6, 5}};
  for (const auto& f : faces) {
    const auto base = static_cast<uint32_t>(mesh.positions.size());
    glm::vec3 n = glm::normalize(glm::cross(c[f[1]] - c[f[0]], c[f[2]] - c[f[0]]));
    if (!outwards) n = -n;
    for (int k = 0; k < 4; ++k) {
      mesh.positions.push_back(c[f[k]]);
      mesh.normals.push_back(n);
    }
    const uint32_t quad[6] = {0, 1, 2, 0, 2, 3};
    for (int k = 0; k < 6; ++k) mesh.indices.push_back(base + quad[outwards ? k : 5 - k]);
  }
}

Scene sceneWith(std::vector<Mesh> meshes) {
  Scene scene;
  scene.materials.push_back(Material{});
  for (uint32_t m = 0; m < meshes.size(); ++m) {
    scene.meshes.push_back(std::move(meshes[m]));
    Instance instance;
    instance.mesh = m;
    scene.instances.push_back(instance);
  }
  return scene;
}

Light pointAt(glm::vec3 p) {
  Light light;
  light.position = p;
  light.intensity = glm::vec3(1.0f);
  return light;
}

// Every triangle of `mesh` (a box about `centre`) faces away from it (+1) or towards it (−1);
// 0 when mixed. Its shading normals must agree with its winding.
int facing(const Mesh& mesh, glm::vec3 centre) {
  int out = 0, in = 0;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const glm::vec3 p0 = mesh.positions[mesh.indices[3 * t]];
    const glm::vec3 n = glm::cross(mesh.positions[mesh.indices[3 * t + 1]] - p0,
                                   mesh.positions[mesh.indices[3 * t + 2]] - p0);
    (glm::dot(n, p0 - centre) > 0.0f ? out : in) += 1;
    for (int k = 0; k < 3; ++k) EXPECT_GT(glm::dot(mesh.normals[mesh.indices[3 * t + k]], n), 0.0f);
  }
  return in == 0 ? 1 : out == 0 ? -1 : 0;
}

TEST(ClosedShells, InsideOutBoxLitFromOutsideIsTurnedOutwards) {
  // The conference room's chair backs: closed, wound inwards, every light outside.
  Mesh box;
  addBox(box, glm::vec3(-0.2f, 0.3f, -0.03f), glm::vec3(0.2f, 0.6f, 0.03f), false);
  Scene scene = sceneWith({box});
  scene.lights.push_back(pointAt({0.0f, 1.8f, 1.0f}));
  ASSERT_EQ(facing(scene.meshes[0], {0.0f, 0.45f, 0.0f}), -1);
  const ShellOrientation result = orientClosedShells(scene);
  EXPECT_EQ(result.closedShells, 1u);
  EXPECT_EQ(result.turned, 1u);
  EXPECT_EQ(facing(scene.meshes[0], {0.0f, 0.45f, 0.0f}), 1);
}

// Meshes are judged each on its own (in parallel) and their shells too: 8 meshes of 4 boxes
// each, every other box inside out, a light above them all; oriented in a 4-thread arena, each
// mesh's inside-out boxes, and only those, are turned.
TEST(ClosedShells, EveryShellOfManyMeshesIsJudgedOnItsOwn) {
  std::vector<Mesh> meshes(8);
  const auto centre = [](int m, int b) { return glm::vec3(m, 0.5f, b); };
  for (int m = 0; m < 8; ++m)
    for (int b = 0; b < 4; ++b)
      addBox(meshes[m], centre(m, b) - 0.2f, centre(m, b) + 0.2f, b % 2 == 0);
  Scene scene = sceneWith(std::move(meshes));
  scene.lights.push_back(pointAt({3.5f, 5.0f, 1.5f}));
  ShellOrientation result;
  tbb::task_arena(4).execute([&] { result = orientClosedShells(scene); });
  EXPECT_EQ(result.closedShells, 32u);
  EXPECT_EQ(result.turned, 16u);
  for (int m = 0; m < 8; ++m)
    for (int b = 0; b < 4; ++b) {
      Mesh box;  // the box's own 12 triangles, as the mesh holds them now
      const Mesh& mesh = scene.meshes[m];
      for (int k = 0; k < 36; ++k) {
        box.indices.push_back(static_cast<uint32_t>(box.positions.size()));
        box.positions.push_back(mesh.positions[mesh.indices[36 * b + k]]);
        box.normals.push_back(mesh.normals[mesh.indices[36 * b + k]]);
      }
      EXPECT_EQ(facing(box, centre(m, b)), 1) << "mesh " << m << ", box " << b;
    }
}

TEST(ClosedShells, BoxWoundHalfInwardsIsWoundOutwardsWhole) {
  // The conference room's curtain-rail ends: closed, but half the faces wound inwards.
  Mesh box;
  addBox(box, glm::vec3(-0.5f), glm::vec3(0.5f), true);
  for (std::size_t t = 0; t < box.triangleCount(); t += 4) {  // faces 0, 2, 4 turned in
    for (std::size_t u = t; u < t + 2; ++u)
      std::swap(box.indices[3 * u + 1], box.indices[3 * u + 2]);
    for (int k = 0; k < 4; ++k) box.normals[2 * t + k] = -box.normals[2 * t + k];
  }
  Scene scene = sceneWith({box});
  scene.lights.push_back(pointAt({0.0f, 3.0f, 0.0f}));
  ASSERT_EQ(facing(scene.meshes[0], glm::vec3(0.0f)), 0);
  const ShellOrientation result = orientClosedShells(scene);
  EXPECT_EQ(result.closedShells, 1u);
  EXPECT_EQ(result.turned, 1u);
  EXPECT_EQ(facing(scene.meshes[0], glm::vec3(0.0f)), 1);
}

TEST(ClosedShells, MirroredInstanceIsJudgedWhereItStands) {
  // Decided in the mesh's own space with the lights brought there: the box (x 1..2 in its
  // mesh, x −2..−1 in the world) with a light inside it in the world is a room and keeps its
  // inward winding; with the light above it, it is turned and faces out in the world, where
  // flatten() reverses a mirroring instance's winding.
  Mesh box;
  addBox(box, glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(2.0f, 1.0f, 1.0f), false);
  const glm::mat4 mirror = glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f));
  const glm::vec3 centre(-1.5f, 0.5f, 0.5f);
  Scene room = sceneWith({box});
  room.instances[0].transform = mirror;
  room.lights.push_back(pointAt(centre));
  EXPECT_EQ(orientClosedShells(room).turned, 0u);
  Scene solid = sceneWith({box});
  solid.instances[0].transform = mirror;
  solid.lights.push_back(pointAt({-1.5f, 3.0f, 0.5f}));
  EXPECT_EQ(orientClosedShells(solid).turned, 1u);
  const WorldGeometry world = flatten(solid);
  for (std::size_t t = 0; t < world.triangleCount(); ++t)
    EXPECT_GT(glm::dot(world.triangleCross(t), world.positions[world.triangles[t].x] - centre),
              0.0f);
}

TEST(ClosedShells, RoomLitFromInsideKeepsItsInwardWinding) {
  Mesh room;
  addBox(room, glm::vec3(-2.0f, 0.0f, -2.0f), glm::vec3(2.0f, 2.5f, 2.0f), false);
  Scene scene = sceneWith({room});
  scene.lights.push_back(pointAt({0.3f, 2.2f, -0.5f}));
  EXPECT_EQ(orientClosedShells(scene).turned, 0u);
  EXPECT_EQ(facing(scene.meshes[0], {0.0f, 1.25f, 0.0f}), -1);
}

TEST(ClosedShells, RoomWoundOutwardsWithItsLightInsideIsTurnedInwards) {
  Mesh room;
  addBox(room, glm::vec3(-2.0f, 0.0f, -2.0f), glm::vec3(2.0f, 2.5f, 2.0f), true);
  Scene scene = sceneWith({room});
  scene.lights.push_back(pointAt({0.3f, 2.2f, -0.5f}));
  EXPECT_EQ(orientClosedShells(scene).turned, 1u);
  EXPECT_EQ(facing(scene.meshes[0], {0.0f, 1.25f, 0.0f}), -1);
}

TEST(ClosedShells, LightOnBothSidesOrNoneOrAnOpenBoxChangesNothing) {
  Mesh box;
  addBox(box, glm::vec3(-1.0f), glm::vec3(1.0f), false);
  Scene both = sceneWith({box});
  both.lights.push_back(pointAt({0.0f, 0.5f, 0.0f}));
  both.lights.push_back(pointAt({0.0f, 3.0f, 0.0f}));
  EXPECT_EQ(orientClosedShells(both).turned, 0u);
  Scene none = sceneWith({box});
  EXPECT_EQ(orientClosedShells(none).turned, 0u);
  // Directional light counts as outside every shell, with the point inside: both sides.
  Scene sun = sceneWith({box});
  sun.lights.push_back(pointAt({0.0f, 0.5f, 0.0f}));
  sun.lights.push_back(Light{"sun", LightType::Directional});
  EXPECT_EQ(orientClosedShells(sun).turned, 0u);
  // An open box (its top face removed) is a single sheet: it keeps its winding.
  Mesh open = box;
  open.indices.resize(open.indices.size() - 6);
  Scene sheet = sceneWith({open});
  sheet.lights.push_back(pointAt({0.0f, 3.0f, 0.0f}));
  const ShellOrientation result = orientClosedShells(sheet);
  EXPECT_EQ(result.closedShells, 0u);
  EXPECT_EQ(result.turned, 0u);
}

TEST(ClosedShells, AnEmitterOutsideCountsAndAnEmittingShellIsLeftAlone) {
  Mesh box, lamp;
  addBox(box, glm::vec3(-0.5f), glm::vec3(0.5f), false);
  addBox(lamp, glm::vec3(-0.1f, 2.0f, -0.1f), glm::vec3(0.1f, 2.1f, 0.1f), false);
  lamp.material = 1;
  Scene scene = sceneWith({box, lamp});
  Material emitter;
  emitter.emission = glm::vec3(5.0f);
  scene.materials.push_back(emitter);
  const ShellOrientation result = orientClosedShells(scene);
  EXPECT_EQ(result.turned, 1u);  // the box, lit by the lamp's (inward) triangles from outside
  EXPECT_EQ(facing(scene.meshes[0], glm::vec3(0.0f)), 1);
  EXPECT_EQ(facing(scene.meshes[1], {0.0f, 2.05f, 0.0f}), -1);  // the lamp as it was written
}

TEST(ClosedShells, OnlyTheInsideOutShellOfAMeshTurns) {
  Mesh mesh;
  addBox(mesh, glm::vec3(0.0f), glm::vec3(1.0f), true);
  addBox(mesh, glm::vec3(2.0f, 0.0f, 0.0f), glm::vec3(3.0f, 1.0f, 1.0f), false);
  Scene scene = sceneWith({mesh});
  scene.lights.push_back(pointAt({1.5f, 3.0f, 0.5f}));
  const ShellOrientation result = orientClosedShells(scene);
  EXPECT_EQ(result.closedShells, 2u);
  EXPECT_EQ(result.turned, 1u);
  Mesh first, second;
  first.positions = second.positions = scene.meshes[0].positions;
  first.normals = second.normals = scene.meshes[0].normals;
  const auto half = scene.meshes[0].indices.begin() + 36;
  first.indices.assign(scene.meshes[0].indices.begin(), half);
  second.indices.assign(half, scene.meshes[0].indices.end());
  EXPECT_EQ(facing(first, glm::vec3(0.5f)), 1);
  EXPECT_EQ(facing(second, {2.5f, 0.5f, 0.5f}), 1);
}

TEST(ClosedShells, AVertexSharedWithATriangleThatKeepsItsWindingIsCopied) {
  Mesh mesh;
  addBox(mesh, glm::vec3(0.0f), glm::vec3(1.0f), false);
  // A sheet (one triangle, open) using the box's vertex 0 by index, facing down.
  const auto base = static_cast<uint32_t>(mesh.positions.size());
  mesh.positions.push_back({1.0f, 0.0f, -1.0f});
  mesh.positions.push_back({0.0f, 0.0f, -1.0f});
  mesh.normals.push_back({0.0f, -1.0f, 0.0f});
  mesh.normals.push_back({0.0f, -1.0f, 0.0f});
  const glm::vec3 sharedNormal = mesh.normals[0];
  mesh.indices.insert(mesh.indices.end(), {0u, base, base + 1});
  Scene scene = sceneWith({mesh});
  scene.lights.push_back(pointAt({0.5f, 3.0f, 0.5f}));
  const std::size_t vertices = scene.meshes[0].positions.size();
  EXPECT_EQ(orientClosedShells(scene).turned, 1u);
  const Mesh& turned = scene.meshes[0];
  EXPECT_EQ(turned.positions.size(), vertices + 1);
  // The sheet is untouched: same indices, same normal at the shared vertex.
  const std::size_t last = turned.indices.size() - 3;
  EXPECT_EQ(turned.indices[last], 0u);
  EXPECT_EQ(turned.normals[0], sharedNormal);
  Mesh box = turned;
  box.indices.resize(last);
  EXPECT_EQ(facing(box, glm::vec3(0.5f)), 1);
}

}  // namespace
}  // namespace bounce
