// VPLs re-traced at run time with the dynamic instances where they are now: instant radiosity
// as Keller ran it, once per placement. The bake's VPLs (vpl_generate.h, staticScene) leave the
// dynamic objects out, so they neither shadow the room nor reflect light into it; cutting the
// bake's paths where a dynamic object blocks them (vpl_runtime/vpl_occlusion.h) restores its shadow
// but not the light it reflects, which is 7–19 % of the dynamic sphere's own indirect light in
// content/cornell_box_dynamic (docs/vpl.md, "Dynamic objects"). Tracing the light paths again
// over the whole scene, with the bake's count rule (cap, error target, seed), gives VPLs that
// carry both, VPLs on the dynamic objects included. Deterministic: the same placement gives the
// same VPLs at any thread count. GL-free; the renderer reaches it through the function its
// settings carry (render/forward_renderer.h, RendererSettings::vplTracer), wired by the apps.
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "bake_folder/vpl.h"
#include "scene/scene.h"
#include "vpl/vpl_generate.h"

namespace bounce {

struct Bake;
struct BakeManifest;

// The count rule a bake's VPLs were traced with, from its bake.json ("vpls": cap, errorTarget;
// "settings": seed; a hand-made manifest leaves them 0: VplSettings{}, bounce-bake's defaults), for
// a bake that holds `bakeVplCount` VPLs. The cap is held to 2·bakeVplCount + kVplBatch: a re-trace
// makes about the bake's count (more only where paths now also bounce off the dynamic objects),
// and a tampered cap must not make a move trace billions of paths.
VplSettings vplSettingsOfBake(const BakeManifest& manifest, std::size_t bakeVplCount);

class PlacedVplTracer {
 public:
  // Keeps its own copy of `scene` (meshes included); only instance transforms change later.
  PlacedVplTracer(const Scene& scene, const VplSettings& settings);

  // VPLs (W per channel, bake_folder/vpl.h) of light paths through the scene with instance i at
  // object → world transforms[i] (one per scene instance; fewer leave the rest where they are).
  // Cost: the scene flattened and a ray kernel built over it, then the paths (~1 + 8 ms on one
  // core for 16384 VPLs in the Cornell box, bench_vpl_occlusion).
  std::vector<Vpl> trace(std::span<const glm::mat4> transforms);

 private:
  Scene scene_;
  VplSettings settings_;
};

// A PlacedVplTracer for `scene` with the count rule of `bake` (read for this scene), as the
// function RendererSettings::vplTracer takes.
std::function<std::vector<Vpl>(std::span<const glm::mat4>)> placedVplTracer(const Scene& scene,
                                                                            const Bake& bake);

}  // namespace bounce
