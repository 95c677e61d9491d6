// Two rooms through one thin wall (docs/real_scenes.md, "Light through thin walls"): a lit and a
// dark room, each 2 m × 2 m × 2.5 m, share ONE floor quad, ONE ceiling quad and two side-wall
// quads that run through a dividing wall (a closed box t thick at x ∈ [−t/2, t/2]), as slabs and
// walls of real levels do. A 10 W/sr point light hangs in the lit room (x < 0); nothing reaches
// the dark room (x > t/2) but through the wall, so its radiance is exactly 0. Built in code, so
// the surfaces are cut where the wall crosses them (scene/crossing_cuts.h) here, as loadScene
// does for files.
#pragma once

#include "scene/crossing_cuts.h"
#include "shadow_scenes.h"
#include "test_scenes.h"

namespace bounce::test {

inline Material matteMaterial(const char* name, float albedo) {
  Material m;
  m.name = name;
  m.albedo = glm::vec3(albedo);
  return m;
}

// The scene before cutting (what a file holds); thinWallRooms cuts it.
inline Scene thinWallRoomsAsWritten(float t) {
  Scene scene;
  const Material white = matteMaterial("wall", 0.75f), floor = matteMaterial("floor", 0.5f);
  const float h = 2.5f;
  addQuad(scene, {-2, 0, 1}, {4, 0, 0}, {0, 0, -2}, floor);  // the floor, up, under the wall
  addQuad(scene, {-2, h, -1}, {4, 0, 0}, {0, 0, 2}, white);  // the ceiling, down, over it
  addQuad(scene, {-2, 0, -1}, {4, 0, 0}, {0, h, 0}, white);  // z = −1, facing +z, through it
  addQuad(scene, {2, 0, 1}, {-4, 0, 0}, {0, h, 0}, white);   // z = +1, facing −z, through it
  addQuad(scene, {-2, 0, 1}, {0, 0, -2}, {0, h, 0}, white);  // x = −2, facing +x
  addQuad(scene, {2, 0, -1}, {0, 0, 2}, {0, h, 0}, white);   // x = +2, facing −x
  addBox(scene, {-t / 2, 0, -1}, {t / 2, h, 1}, white);      // the dividing wall
  scene.lights.push_back(pointAt({-1.0f, 2.0f, 0.3f}, 10.0f));
  return scene;
}

inline Scene thinWallRooms(float t) {
  Scene scene = thinWallRoomsAsWritten(t);
  cutAtCrossings(scene);
  return scene;
}

}  // namespace bounce::test
