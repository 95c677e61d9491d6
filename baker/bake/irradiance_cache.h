// The lightmap's own irradiance as a cache the final gather ends its paths at
// (trace/indirect_cache.h; docs/baker.md, "Gather with a cache").
//
// Holds two whole-map E_cache (W/m², per linear-RGB channel, the layout's size: the total
// irradiance of two short bakes of seeds of their own, each dilated as the final map is, not
// denoised, holdsDirect; or the delivered map twice, indirect only, for the probes) and a mask of
// the texels they may be read at. A final sample of half h
// (delivered_error.h's split) reads half(h) only, so the final pass's two half-sample maps carry
// independent cache errors and their difference D holds the cache's noise as well as the final
// samples' (docs/baker.md, "Gather with a cache"). A hit y reached from the vertex x reads the
// texel under y's atlas position (its triangle's corner UVs at its barycentrics, nearest texel)
// unless one of the guards says the texel's value is not y's irradiance:
//   close     |y − x| < kCloseTexels texel edges at y: at a corner or in a narrow slot the texel
//             averages E over an area across which E changes fast (and its points were chosen
//             away from the corner by the leak guard), so y's own E differs from the texel's;
//   back      y is seen from its back face: the texel holds the front side's light (the one side
//             a lightmap holds, docs/baker.md);
//   no region y's instance has no lightmap region (probe- or VPL-lit statics, dynamic ones);
//   invalid   y's texel is not in the mask (uncovered, or every point of it dropped by the leak
//             guard: inside geometry), so its value is a neighbour's.
// Each guard sends the path on as without a cache. GL-free.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "image/image.h"
#include "trace/indirect_cache.h"

namespace bounce {

struct LightmapLayout;
struct Scene;
struct WorldGeometry;

// Texel edges at the hit under which the close guard refuses the cache (see above).
inline constexpr float kCloseTexels = 2.0f;

class IrradianceCache {
 public:
  // Each of `halves` and `readable` (per texel, 1 where the cache may be read) is layout.width ×
  // layout.height; geometry = flatten(scene), whose instances the layout's regions number.
  // Throws std::invalid_argument when the sizes or the layout do not fit the scene.
  IrradianceCache(const Scene& scene, const WorldGeometry& geometry, const LightmapLayout& layout,
                  std::array<Image, 2> halves, std::vector<uint8_t> readable,
                  bool holdsDirect = false);
  // half_ points into this object.
  IrradianceCache(const IrradianceCache&) = delete;
  IrradianceCache& operator=(const IrradianceCache&) = delete;

  // The cache the final samples of half h (0: A, 1: B) read.
  const IndirectCache& half(int h) const { return half_[h & 1]; }
  // E_cache of half h (W/m²) at `at`, the hit of a ray from `from`; nullopt where a guard refuses.
  std::optional<glm::vec3> irradianceAt(const SurfacePoint& at, glm::vec3 from, int h) const;

  // The texel under world triangle `triangle` at barycentrics `uv` (Hit::u, Hit::v), or nullopt
  // where the triangle has no lightmap region.
  std::optional<std::size_t> texelAt(uint32_t triangle, glm::vec2 uv) const;

 private:
  struct TriangleUv {
    glm::vec2 corner[3];     // atlas texel coordinates of the world triangle's corners
    float texelEdge = 0.0f;  // metres on the surface per texel edge; 0: no lightmap region
  };
  class Half final : public IndirectCache {
   public:
    Half(const IrradianceCache& owner, int h) : owner_(owner), h_(h) {}
    std::optional<glm::vec3> irradianceAt(const SurfacePoint& at, glm::vec3 from) const override {
      return owner_.irradianceAt(at, from, h_);
    }
    bool holdsDirect() const override { return owner_.holdsDirect_; }

   private:
    const IrradianceCache& owner_;
    int h_;
  };
  const WorldGeometry& geometry_;
  std::array<Image, 2> irradiance_;
  std::array<Half, 2> half_{Half(*this, 0), Half(*this, 1)};
  std::vector<uint8_t> readable_;
  std::vector<TriangleUv> triangles_;  // per world triangle
  bool holdsDirect_ = false;           // E_total, not E_indirect (IndirectCache::holdsDirect)
};

}  // namespace bounce
