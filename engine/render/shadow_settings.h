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
  // A static spot or point light whose visibility the bake holds on every static surface draws
  // a map only while a dynamic instance is in its reach; static surfaces then read the texels' V
  // alone (docs/shadows.md). On by default since a chart without points (a strip inside a thin
  // wall, drawn at a multisampled edge pixel) is baked dark to every light (fillVisibility), not
  // lit from across the wall; false keeps a map for every shadowed light as before.
  bool bakedPunctualMapsOnlyForDynamic = true;
};

// What a shadow pass drew in one frame: map views (a spot map, a cube face) and instances drawn
// into them, summed over views; what culling saves shows here.
struct ShadowDrawCount {
  int views = 0;
  int casters = 0;
  ShadowDrawCount& operator+=(const ShadowDrawCount& other) {
    views += other.views;
    casters += other.casters;
    return *this;
  }
};

}  // namespace bounce
