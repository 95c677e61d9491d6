// How shadow maps are made and filtered. Defaults are chosen per light from the scene (see
// docs/shadows.md); the fields here override them, e.g. for benchmarks.
#pragma once

namespace bounce {

enum class ShadowFilter {
  Hardware,  // one comparison tap: GL_LINEAR comparison = bilinear 2×2 PCF
  Poisson,   // 16 Poisson-disk taps, rotated per pixel, each a hardware 2×2 tap
};

struct ShadowSettings {
  bool enabled = true;
  // Texels per side of a spot map / of each face of a point light's cube map; 0 = chosen per
  // light from the scene's size (docs/shadows.md).
  int resolution = 0;
  ShadowFilter filter = ShadowFilter::Poisson;
  // Radius of the Poisson kernel in texels of the map (ignored by Hardware).
  float filterRadius = 1.5f;
};

}  // namespace bounce
