// The clamp distance of a VPL set (docs/vpl.md, "The clamp"): the geometry term 1/d² of every
// VPL is capped at 1/r² with
//     r = sqrt(A / (π·N))                                    [m]
// A the scene's surface area (m²) and N the VPL count: the radius of the disc each VPL covers
// when N are spread evenly over A. Within r a VPL is replaced by (at most) that disc's light.
// GL-free: the baker writes r into bake.json "vpls"."clampDistance", the renderer reads it.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "bake_folder/bake_manifest.h"
#include "scene/world_geometry.h"

namespace bounce {

// r = sqrt(A/(π·N)), metres; 0 when N = 0 or A ≤ 0.
float vplClampDistance(double surfaceArea, std::size_t vplCount);
// Σ triangle areas, m² (non-finite areas skipped).
double surfaceArea(const WorldGeometry& geometry);
// The clamp's A: Σ triangle areas of the static instances (the surfaces VPLs are generated on),
// m², non-finite areas skipped. `geometry` is flatten(scene); the baker passes its static scene
// (every instance static), the renderer the whole one: both sum the same triangles in the same
// order, so the baker's r and the renderer's fallback for a manifest without one agree.
double staticSurfaceArea(const Scene& scene, const WorldGeometry& geometry);
// The same, flattening `scene` itself.
double staticSurfaceArea(const Scene& scene);
// bake.json's "vpls"."clampDistance" (m; the reader keeps it in [0, kMaxBakeLength]), nullopt
// when the manifest describes no VPLs.
std::optional<float> manifestVplClampDistance(const BakeManifest& manifest);

}  // namespace bounce
