// The clamp distance of a VPL set (docs/vpl.md, "The clamp"): the geometry term 1/d² of every
// VPL is capped at 1/r² with
//     r = sqrt(A / (π·N))                                    [m]
// A the scene's static surface area (m², scene/static_scene.h: staticSurfaceArea, every static
// instance's triangles, those at lightmapScale 0 too: VPLs land on them) and N the VPL count:
// the radius of the disc each VPL covers when N are spread evenly over A. Within r a VPL is
// replaced by (at most) that disc's light. GL-free: the baker writes r into bake.json
// "vpls"."clampDistance", the renderer reads it.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "bake_folder/bake_manifest.h"
#include "scene/static_scene.h"  // staticSurfaceArea, surfaceArea: the clamp's A

namespace bounce {

// r = sqrt(A/(π·N)), metres; 0 when N = 0 or A ≤ 0.
float vplClampDistance(double surfaceArea, std::size_t vplCount);
// bake.json's "vpls"."clampDistance" (m; the reader keeps it in [0, kMaxBakeLength]), nullopt
// when the manifest describes no VPLs.
std::optional<float> manifestVplClampDistance(const BakeManifest& manifest);

}  // namespace bounce
