// The lightmap atlas: gives every static instance its own region of one lightmap. GL-free.
//
// A mesh's own lightmap UVs (glTF TEXCOORD_1, Mesh::uv1) are used when valid (inside [0,1], no
// overlapping triangles, enough texels per triangle); otherwise charts are generated: region
// growing over the half-edge structure with a normal-cone bound, planar projection for
// near-planar charts and least-squares conformal maps for the rest, every chart scaled to one
// world-space texel density, packed with `padding` texels around each chart.
#pragma once

#include <string>
#include <vector>

#include "atlas/texel_density.h"
#include "bake_folder/lightmap_layout.h"
#include "scene/scene.h"

namespace bounce {

// An instance whose surface (area × lightmapScale²) covers fewer texels than this gets no
// lightmap: a chair leg or a screw narrower than a texel would only be padding around a smear.
// Its baked light comes from irradiance probes around it (bake/irradiance_probes.h; from the VPLs,
// as a dynamic instance's, in a bake without probes). A user overrides it with
// extras.bounce.lightmapScale: 0 sends any instance to the probes, a larger scale gives a small
// one enough texels to keep a lightmap.
inline constexpr double kMinLightmapTexels = 2.0;

// An instance whose surface fills less than this share of the texels its charts take, each
// chart's touched texels grown by padding/2 (its share of the padding), gets no lightmap either:
// its lightmap would be mostly padding around pieces smaller than a texel (a chair's frame, a
// cluster of 240 small boxes, wheels), each texel a smear over them. A single square chart of
// side s texels, fully covered, fills s²/(s + 2)² with padding 2: 0.3 at s = 2.4 (12 cm at 5 cm
// texels). Its light comes from the probes; a larger extras.bounce.lightmapScale raises the fill
// (texels shrink against the pieces) and keeps a lightmap, AtlasSettings::minLightmapFill = 0
// turns the rule off.
inline constexpr double kMinLightmapFill = 0.3;

// ... unless most of its surface is what its lightmap resolves and the probes do not: an instance
// with at least kMinResolvedShare of its area in triangles of at least kCoarseTriangleTexels
// texels² lying in charts at least kResolvedChartTexels texels across both ways keeps its
// lightmap whatever its fill. A probe-lit instance's direct light is shadowed by visibility per
// triangle corner, interpolated linearly across each triangle: a finely tessellated chair is
// resolved by its corners, a whiteboard of two triangles is not (its shadow shows the diagonal),
// nor is it by one grid of probes (blotchy); its own texels resolve it, and the trims that share
// its mesh take their texels and padding with it. Conference Room: the whiteboard (`mesh16`,
// fill 0.16, 60 % of it so resolved) keeps its lightmap, the chairs (29 to 39 %) and the 240
// boxes do not (docs/lightmap_atlas.md, step 7).
inline constexpr double kCoarseTriangleTexels = 8.0;
inline constexpr int kResolvedChartTexels = 4;
inline constexpr double kMinResolvedShare = 0.5;

struct AtlasSettings {
  // Texel edge in metres where an instance's lightmapScale is 1 (instance i's is texelSize/s_i).
  // 0 = the density rule of texel_density.h (or √(A / texelBudget) when texelBudget > 0).
  float texelSize = 0.0f;
  int texelBudget = 0;                    // texels the static surface should cover; 0 = the rule
  int64_t maxTexels = kDefaultMaxTexels;  // cap on the texels the surface takes (texel_density.h)
  int padding = 2;     // texels between charts (dilation and bilinear filtering need ≥ 2)
  int maxSize = 4096;  // largest atlas edge, texels
  // Instances whose surface fills less than this share of their charts' padded texels take the
  // VPLs' light (kMinLightmapFill); 0 keeps a lightmap for every instance over kMinLightmapTexels.
  double minLightmapFill = kMinLightmapFill;
};

struct Atlas {
  LightmapLayout layout;
  std::vector<std::string> notes;  // one sentence each: why a mesh's own uv1 was not used, …
  // Static instances left without a lightmap region, their baked light taken from irradiance
  // probes (bake/irradiance_probes.h; the name is from when the VPLs lit them): lightmapScale 0,
  // under kMinLightmapTexels of surface at their texel, or filling under minLightmapFill of their
  // charts' padded texels.
  std::vector<uint32_t> vplLitInstances;
  // Added to the interface: the chart of every triangle, parallel to layout.instances[i].cornerUv
  // (one per triangle), chart ids in [0, layout.chartCount). Texels of different charts never
  // neighbour within `padding`; filters (dilation, denoiser, seams) must not mix charts.
  std::vector<std::vector<uint32_t>> triangleChart;
  // Added to the interface, for reports (bake.json, bounce-atlas): what the charts are.
  struct ChartKinds {
    int planar = 0;      // planar projections of (near-)flat regions
    int conformal = 0;   // least-squares conformal maps of curved regions
    int meshUv1 = 0;     // instances laid out by their mesh's own TEXCOORD_1 (one chart each)
    int degenerate = 0;  // groups of area-less triangles (one texel each)
    int bundle = 0;      // sub-texel pieces that lie close and face one way, side by side
  } chartKinds;
  // m², surface of all static instances (world space), those at lightmapScale 0 too:
  // scene/static_scene.h's staticSurfaceArea, the VPL clamp's A.
  double staticArea = 0.0;
  // m², Σ area × lightmapScale²: the area the texel density applies to.
  double weightedArea = 0.0;
  std::string texelRule;  // how the texel size was chosen (TexelDensity::rule)
};

// Throws std::invalid_argument for settings that make no sense (padding < 0, texelSize < 0,
// texelBudget < 0, maxTexels < 1, maxSize < 1). A scene without static surface gives an empty
// layout (0 × 0). When the texel cap coarsens the texels, a note says so; when the charts do not
// fit in maxSize², the texel size grows by 10 % until they do (with a note); throws
// std::runtime_error when they do not fit even at one texel each.
Atlas buildAtlas(const Scene& scene, const AtlasSettings& settings);

}  // namespace bounce
