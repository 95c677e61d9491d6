// A sampler object that reads depth textures as plain values (no comparison): a shader's
// `samplerCube` / `sampler2D` on a unit this is bound to gets the stored depth itself, bilinearly
// filtered, whatever comparison mode the texture has (a sampler object overrides the texture's
// own sampling state). Percentage-closer soft shadows need the stored depths for their blocker
// search (shaders/shadow_area.glsl).
#pragma once

#include <cstdint>

namespace bounce::gl {

class DepthValueSampler {
 public:
  DepthValueSampler();
  ~DepthValueSampler();
  DepthValueSampler(const DepthValueSampler&) = delete;
  DepthValueSampler& operator=(const DepthValueSampler&) = delete;

  // Reads every texture bound to texture unit `unit` through this sampler; also turns on
  // seamless cube-map filtering for the context.
  void bind(int unit) const;

 private:
  uint32_t id_ = 0;
};

}  // namespace bounce::gl
