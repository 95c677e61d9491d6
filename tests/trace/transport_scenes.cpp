#include "transport_scenes.h"

namespace bounce::test {

namespace {
constexpr float kFov = 1.0471976f;  // 60°
}

World furnace(float albedo, glm::vec3 le) {
  World world;
  addInwardBox(world.scene, glm::vec3(-1.0f), glm::vec3(1.0f),
               addMaterial(world.scene, glm::vec3(albedo), le));
  return world;
}

Camera furnaceCamera() {
  return lookAt({0.1f, 0.2f, 0.05f}, {0.3f, -0.2f, -1.0f}, {0, 1, 0}, 1.5f);
}

World corridor() {
  World world;
  const uint32_t wall = addMaterial(world.scene, glm::vec3(0.7f, 0.6f, 0.5f));
  addInwardBox(world.scene, {0, 0, 0}, {4, 2, 2}, wall);
  addQuad(world.scene, {2, 0, 0}, {2, 2, 0}, {2, 2, 1.5f}, {2, 0, 1.5f}, wall);
  const uint32_t light = addMaterial(world.scene, glm::vec3(0.0f), glm::vec3(20.0f, 18.0f, 15.0f));
  addQuad(world.scene, {0.5f, 0.75f, 0.01f}, {1.0f, 0.75f, 0.01f}, {1.0f, 1.25f, 0.01f},
          {0.5f, 1.25f, 0.01f}, light);
  return world;
}

Camera corridorCamera() {
  return lookAt({3.8f, 1.0f, 1.0f}, {2.5f, 1.0f, 0.0f}, {0, 0, 1}, kFov);
}

namespace {

// The slit rooms with walls of albedo `wallAlbedo`.
World slitRoomsWithWalls(bool withPartition, float wallAlbedo) {
  World world;
  const uint32_t wall = addMaterial(world.scene, glm::vec3(wallAlbedo));
  addInwardBox(world.scene, {0, 0, 0}, {4, 2, 2}, wall);
  if (withPartition) {
    addQuad(world.scene, {kSlitX, 0, 0}, {kSlitX, kSlitY0, 0}, {kSlitX, kSlitY0, 2}, {kSlitX, 0, 2},
            wall);
    addQuad(world.scene, {kSlitX, kSlitY1, 0}, {kSlitX, 2, 0}, {kSlitX, 2, 2}, {kSlitX, kSlitY1, 2},
            wall);
  }
  const uint32_t light = addMaterial(world.scene, glm::vec3(0.0f), glm::vec3(kSlitLightLe));
  addQuad(world.scene, {kSlitLightX0, kSlitLightY0, kSlitLightZ},
          {kSlitLightX0, kSlitLightY1, kSlitLightZ}, {kSlitLightX1, kSlitLightY1, kSlitLightZ},
          {kSlitLightX1, kSlitLightY0, kSlitLightZ}, light);
  return world;
}

}  // namespace

World slitRooms(bool withPartition) {
  return slitRoomsWithWalls(withPartition, 0.7f);
}

World blackSlitRooms(bool withPartition, float floorAlbedo) {
  World world = slitRoomsWithWalls(withPartition, 0.0f);
  // addInwardBox lists the floor (z = 0, facing +z) first.
  world.scene.meshes[0].material = addMaterial(world.scene, glm::vec3(floorAlbedo));
  return world;
}

Camera slitFloorCamera() {
  return lookAt({3.0f, 1.0f, 1.5f}, {3.0f, 1.0f, 0.0f}, {1, 0, 0}, kFov);
}

Camera slitCamera() {
  return lookAt({3.9f, 1.5f, 1.0f}, {2.5f, 0.6f, 0.6f}, {0, 0, 1}, kFov);
}

}  // namespace bounce::test
