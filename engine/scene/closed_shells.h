// Which side of a closed surface is the lit one, decided once for the renderer and the baker.
//
// The physics: light enters the inside of a closed surface (a shell: every edge shared by
// exactly two triangles wound oppositely) only from sources inside it. So a shell with every
// light source outside it (a chair back, a table leg) is lit only on its outside, and a shell
// with every source inside it (a room modelled as a closed box) only on its inside. Triangles
// face the side their counter-clockwise winding points to (scene.h), and that side is the one
// the renderer draws (single-sided materials are culled from behind) and the one the lightmap
// holds (one irradiance per texel). A shell wound towards its dark side (an inside-out chair
// back exported with inward normals) would show its never-lit inside: black in the lightmap,
// though the path tracer, which reflects on both faces, lights its outside.
//
// orientClosedShells winds every closed shell lit on one side only towards that side: it
// reverses the triangles wound towards the dark side (all of an inside-out shell, or the part
// of a shell an exporter wound against the rest) and turns their shading normals with them. The
// path tracer's image does not change (it reflects on both faces, and shells that emit are left as
// they are). Open surfaces (single sheets), shells lit from both sides, and shells with no light on
// either side keep their winding.
#pragma once

#include <cstddef>

#include "scene/scene.h"

namespace bounce {

struct ShellOrientation {
  std::size_t closedShells = 0;  // closed, orientable components of the scene's meshes
  std::size_t turned = 0;        // of them, with triangles turned to face their lit side
};

// Light sources: point and spot lights at their positions, directional lights outside every
// shell (at infinity), and every emitting triangle (a point just off its centroid on each side
// it emits to). A source that lies on a shell (within a quarter turn of the winding number)
// counts on both sides. Decided per mesh over all its instances; meshes with an emissive
// material are left alone.
ShellOrientation orientClosedShells(Scene& scene);

}  // namespace bounce
