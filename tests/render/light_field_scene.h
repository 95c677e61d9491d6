// A field of point lights over a large floor, for light culling's tests and benchmark: `count`
// point lights on a jittered square grid `spacing` metres apart, 0.5–1.5 m above a floor
// (ρ = 0.5) that extends `spacing` beyond the outermost row, intensities log-uniform over
// [iMin, iMax] W/sr with varied colours; fixed pseudo-random values (std::mt19937 with `seed`).
// The camera stands 3 m above one edge and looks across the field, 20° down.
#pragma once

#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/scene.h"
#include "test_scenes.h"

namespace bounce::test {

struct LightField {
  Scene scene;
  Camera camera;
  float side = 0.0f;  // floor side, metres
};

inline LightField lightField(int count, float spacing, float iMin, float iMax, unsigned seed = 1) {
  LightField field;
  const int across = static_cast<int>(std::ceil(std::sqrt(static_cast<float>(count))));
  field.side = spacing * static_cast<float>(across + 1);
  const float half = 0.5f * field.side;
  Material floor;
  floor.name = "floor";
  floor.albedo = glm::vec3(0.5f);
  addQuad(field.scene, {-half, 0, half}, {field.side, 0, 0}, {0, 0, -field.side}, floor);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int i = 0; i < count; ++i) {
    Light light;
    light.name = "point" + std::to_string(i);
    const float x = -half + spacing * (static_cast<float>(i % across) + 0.5f + u(rng));
    const float z = half - spacing * (static_cast<float>(i / across) + 0.5f + u(rng));
    light.position = {x, 0.5f + u(rng), z};
    const glm::vec3 colour(0.4f + 0.6f * u(rng), 0.4f + 0.6f * u(rng), 0.7f);
    light.intensity = iMin * std::pow(iMax / iMin, u(rng)) * colour;
    field.scene.lights.push_back(light);
  }
  field.camera.name = "edge";
  field.camera.yfov = 1.0f;
  field.camera.znear = 0.05f;
  field.camera.zfar = 2.0f * field.side;
  const glm::vec3 eye(0.0f, 3.0f, half);
  const glm::vec3 ahead(0.0f, -std::tan(glm::radians(20.0f)), -1.0f);
  field.camera.cameraToWorld = glm::inverse(glm::lookAt(eye, eye + ahead, glm::vec3(0, 1, 0)));
  field.scene.cameras.push_back(field.camera);
  return field;
}

}  // namespace bounce::test
