// The scene's point, spot and directional lights as their section of the light table
// (render/light_table.h, shaders/light_table.glsl): every light, no cap.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace bounce {

class PunctualLights {
 public:
  explicit PunctualLights(const Scene& scene);

  std::size_t size() const { return lights_.size(); }
  // The scene light at table index `i` (= Scene::lights[i]).
  const Light& light(std::size_t i) const { return lights_[i]; }
  std::span<const Light> all() const { return lights_; }
  void setLight(std::size_t i, const Light& light) { lights_.at(i) = light; }
  // 4 texels per light (light_table.h), light i's shadow map slot among its kind's maps being
  // shadowSlots[i] (−1: unshadowed; render/shadow_pass.h).
  std::vector<glm::vec4> texels(std::span<const int> shadowSlots) const;
  // The power light `i` is drawn with (its table texel 2): W/sr, or W/m² for directional; 0
  // while its direct light is in the lightmap.
  glm::vec3 drawnPower(std::size_t i) const;
  // Lights marked Light::bakeDirect have their direct light in the lightmap once a bake is
  // attached: then they are drawn with zero power (they keep their place in the table).
  // Without a bake they are drawn live like the others.
  void setBakedDirectInLightmap(bool inLightmap) { bakedDirectInLightmap_ = inLightmap; }
  // The bake's visibility names light i as first + i for i < count (bake_folder/
  // light_visibility.h; count 0: none). Light i reads it while it is static and where the bake
  // saw it: moved or turned (setLight), it has its shadow map alone.
  void setBakedVisibility(int first, std::size_t count) {
    bakedFirst_ = first;
    bakedCount_ = count;
  }
  // Light i's index in the baked visibility, −1 for none.
  int bakedIndex(std::size_t i) const;
  // Whether light i is as the bake saw it in every respect, its power and colour too: only then
  // can its direct light on static surfaces be computed once (render/static_direct_texels.h).
  bool asBaked(std::size_t i) const;
  // Which lights' direct light on static surfaces the texels and corners hold (per light, 1:
  // held; the table's texel 3 z, shaders/lights.glsl); empty: none.
  void setPrecomputed(std::vector<uint8_t> precomputed) { precomputed_ = std::move(precomputed); }
  bool precomputed(std::size_t i) const { return i < precomputed_.size() && precomputed_[i]; }
  // The order the light lists visit the lights in (render/light_grid.h): the precomputed lights
  // without a shadow map this frame first, then the rest, each ascending. A static pixel walks
  // its list from the end and stops at the first of them (shaders/lights.glsl).
  std::vector<uint32_t> listOrder(std::span<const int> shadowSlots) const;

 private:
  bool bakedDirectInLightmap_ = false;
  int bakedFirst_ = 0;
  std::size_t bakedCount_ = 0;
  std::vector<Light> lights_;
  std::vector<Light> baked_;  // the scene's lights, as the bake saw them
  std::vector<uint8_t> precomputed_;
};

}  // namespace bounce
