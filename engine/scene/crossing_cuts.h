// Cutting static surfaces where other static geometry crosses them, so that the lightmap never
// holds both sides of a wall in one chart. GL-free; run by loadScene (scene/load.h) before the
// baker and the renderer see the scene, so both draw and bake the same triangles.
//
// A wall standing on a floor slab (or passing through a ceiling or a side wall) divides that
// surface into regions that see different light: the lit room's side and the dark room's side.
// A lightmap texel holds one value, and the bilinear lookup blends neighbouring texels, so a
// chart that runs continuously under a wall thinner than two texels shows one room's light in
// the other. The cure is topological: the receiving triangle is split along the crossing plane,
// the new edges are marked in Mesh::cutEdges, and the atlas never grows a chart across them; the
// pieces become separate charts, padded apart, that no filter mixes.
//
// The cut rule, per receiving triangle T and per plane P of crossing triangles (a wall face):
//   * a crossing triangle is one of another static surface (any static instance, the same mesh
//     included) that meets T's plane at an angle (not coplanar, not nearly parallel) along a
//     segment inside T: it passes through T, or stands on it;
//   * the crossing line (P against T's plane, over all the receiving instance's triangles in
//     that plane) must run unbroken for at least kMinCutLength: a wall's foot, not the few
//     centimetres where a chair's parts meet, a table leg's foot or a pipe's; those would only
//     chop furniture and floors into charts (the leak guard handles their small footprints);
//     a curved receiver (its facets each in their own plane) is therefore not cut;
//   * when the crossing segments in P cover at least kCoverage of T's chord along P, T is split
//     by P across the whole chord: a wall with a door still cuts the floor across the doorway,
//     so that no chart reaches around the wall's end through the door; when they cover less
//     (T reaches far past the wall's end), T is not cut.
// Every resulting edge on a cut plane gets the chart bit; one whose midpoint lies on a crossing
// triangle (the physical crossing, not its extension across a doorway) gets the crossed bit:
// seam stitching may join the two sides of an extension but never of a crossing.
#pragma once

#include <cstddef>

#include "scene/scene.h"

namespace bounce {

// Fraction of the chord of T along a crossing plane the crossings must cover for a cut.
inline constexpr double kCoverage = 0.5;
// Metres: the shortest unbroken crossing line (over one receiving instance) that cuts.
inline constexpr double kMinCutLength = 0.5;

struct CrossingCuts {
  std::size_t cutTriangles = 0;    // receiving triangles split
  std::size_t addedTriangles = 0;  // triangles the splits added
  std::size_t cutInstances = 0;    // static instances whose mesh was split (copied when shared)
};

// Splits the triangles of static instances (lightmapScale > 0) where static geometry crosses
// them, interpolating normals, uv0 and uv1 at the new vertices; marks the cut edges in
// Mesh::cutEdges. A mesh shared with other instances is copied first. Idempotent: a second call
// finds nothing left to split.
CrossingCuts cutAtCrossings(Scene& scene);

}  // namespace bounce
