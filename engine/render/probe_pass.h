// The probe stage of the lit pass (shaders/probes.glsl): uploads a bake's irradiance probes
// (bake_folder/irradiance_probes.h) as one RGBA32F texture buffer, 3 texels per probe, and tells
// the forward shader, per draw, the grid of the instance drawn: a static instance without a
// lightmap region takes its baked light ρ/π·E(n) from its grid's 8 probes around the pixel
// (constant work per pixel), not from the VPLs. Without probes it binds a 1-texel stand-in and
// no draw reads it. GL calls only through engine/gl.
//
// Texel c (0, 1, 2: red, green, blue) of probe i, at 3i + c: (Y00·E00, Y1·E11, Y1·E1−1, Y1·E10)
// of channel c, so that E_c(n) = t.x + dot(t.yzw, n) (W/m²).
//
// The same instances' baked visibility of the static lights, per triangle corner
// (ProbeVisibility), is a second texture buffer, 2 texels per corner: (the 4 slots' light
// indices, −1 empty, −2 every other light), (their V). A draw of such an instance reads it in
// place of the lightmap's visibility table (shaders/baked_visibility.glsl), so its direct light
// needs no shadow map of a static light for the static occluders.
//
// With attachStaticDirect, a third buffer holds the static lights' irradiance vectors per
// corner (static_direct_corners.h), 3 texels per corner (F_r, F_g, F_b in xyz, w = 1 where the
// triangle reads them): those triangles read their direct light there instead of evaluating the
// lights per pixel.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "gl/shader.h"
#include "gl/texture_buffer.h"

namespace bounce {

struct IrradianceProbes;  // bake_folder/irradiance_probes.h
struct ProbeVisibility;

// The 3 texels of each probe, in order (the layout above).
std::vector<glm::vec4> probeTexels(const IrradianceProbes& probes);
// The 2 texels of each corner of the probes' visibility, in order (the layout above).
std::vector<glm::vec4> cornerVisibilityTexels(const ProbeVisibility& visibility);

class ProbePass {
 public:
  ProbePass();
  // `probes` already checked against the scene by readBake; `instances` the scene's count.
  // `visibility`: whether the draws read the corners' visibility (the lightmap pass has the
  // bake's visibility table, whose light numbering and counts the corners share).
  void attach(const IrradianceProbes& probes, std::size_t instances, bool visibility);
  // Whether instance `index` (into GpuScene::instances) takes its baked light from probes.
  bool probeLit(std::size_t index) const { return index < gridOf_.size() && gridOf_[index] >= 0; }
  // Whether instance `index` reads the static lights' visibility per corner.
  bool cornerVisibility(std::size_t index) const {
    return visibility_ && probeLit(index) &&
           grids_[static_cast<std::size_t>(gridOf_[index])].cornerCount > 0;
  }
  std::size_t probeCount() const { return probeCount_; }
  // Uploads the static lights' F_r, F_g, F_b per corner of the attached probes' visibility
  // (static_direct_corners.h, 3 per corner, w = 1 where read); an empty span, or corner visibility
  // off, drops them.
  void attachStaticDirect(std::span<const glm::vec4> corners);
  bool hasStaticDirect() const { return staticDirect_.has_value(); }

  // Per frame: the buffer.
  void bind(gl::Program& program) const;
  // Per draw: instance `index`'s grid, or uHasProbes false.
  void setInstance(gl::Program& program, std::size_t index) const;

 private:
  std::optional<gl::TextureBuffer> buffer_;
  std::optional<gl::TextureBuffer> corners_;
  std::optional<gl::TextureBuffer> staticDirect_;
  bool visibility_ = false;
  // What a draw reads of its instance's grid (ProbeGrid of bake_folder/irradiance_probes.h).
  struct Grid {
    int first = 0;  // its first probe
    glm::ivec3 counts{2};
    glm::vec3 origin{0.0f}, spacing{0.0f};  // m
    float normalOffset = 0.0f;              // m
    int firstCorner = 0, cornerCount = 0;   // its corners' visibility
  };
  std::vector<Grid> grids_;
  std::vector<int> gridOf_;  // per instance, index into grids_ or −1
  std::size_t probeCount_ = 0;
};

}  // namespace bounce
