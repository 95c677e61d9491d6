// The largest values bounce accepts from a scene file (docs/input_limits.md). A file beyond
// one is a LoadError naming the file and the limit, never a silent infinity later: the limits
// are chosen so that every product the renderer and the tracer form stays finite in float.
#pragma once

#include <cmath>
#include <cstddef>

#include <glm/vec3.hpp>

namespace bounce {

// |x|, |y|, |z| of every vertex (in its mesh and after its instance's transform), light and
// camera position, in metres. Float spacing at 1e6 m is 6.25 cm, so a scene beyond it cannot
// hold centimetre geometry, and squared distances (≤ (2√3·1e6)² = 1.2e13 m²) stay far from
// float's 3.4e38.
inline constexpr double kMaxCoordinate = 1e6;
inline bool withinCoordinateLimit(const glm::dvec3& p) {
  return std::abs(p.x) <= kMaxCoordinate && std::abs(p.y) <= kMaxCoordinate &&
         std::abs(p.z) <= kMaxCoordinate;
}

// Radiometric values after the photometric conversion (units.h), per channel:
//   point/spot intensity (W/sr), directional irradiance (W/m²), emitted radiance (W/(sr·m²)).
// 1e12 is ~1e9 times the sun's irradiance; the tracer's smallest shadow-ray length (its ray
// offset, ≥ 7.6 µm) keeps I/d² ≤ 1e12 / 5.8e-11 ≈ 1.7e22, and an emitter's power
// π·L·A ≤ π·1e12·(2√3·1e6)² ≈ 3.8e25 W per triangle, finite in float.
inline constexpr double kMaxRadiometric = 1e12;

// Camera near plane (metres): below 1e-6 m a float depth buffer has no precision left and the
// frame comes out black.
inline constexpr double kMinZnear = 1e-6;

// Texture width and height (texels): GL_MAX_TEXTURE_SIZE of llvmpipe (Mesa 22.3) is 16384, the
// smallest maximum bounce runs on; and at most 2^26 texels in all (768 MiB as float RGB).
// Largest extras.bounce.lightmapScale: 64× the scene's texels per metre (4096× per m²).
inline constexpr double kMaxLightmapScale = 64.0;

inline constexpr int kMaxTextureSide = 16384;
inline constexpr std::size_t kMaxTextureTexels = std::size_t{1} << 26;

}  // namespace bounce
