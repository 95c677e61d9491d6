#!/usr/bin/python3
"""Writes atrium.gltf: a sunlit courtyard with two storeys of arcades (standard library only).

A lightmapper's hard case: most of what is seen is lit by bounced light of very different
strength, from the sunlit courtyard floor to the back of the upper galleries.
- The courtyard, 8 m x 8 m, open to the sky (nothing above it: a ray leaving it meets no light);
  its floor is textured stone tiles (a 64 x 64 PNG repeated every 2 m).
- Around it a ring of galleries 3 m deep on two storeys: ground arcade (floor y = 0) and upper
  gallery (floor slab at y = 3.5 m, 25 cm thick), under a roof slab at y = 7 m. Each storey
  opens onto the courtyard between square columns (35 cm) every 2 m, under a 50 cm lintel; the
  upper gallery has a parapet 1 m high between its columns. The outer walls (30 cm) are plaster
  (a 64 x 64 PNG repeated every 2 m).
- Sun: a directional light of 12 W/m^2 per channel at (1, 0.93, 0.82) (8196 lux,
  engine/scene/units.h), coming down at 58 degrees: its patch covers most of the courtyard
  floor and reaches into the ground arcade on one side.
- Two point lights (lanterns) hang in the ground arcade at 2.6 m, 10 W/sr warm, on opposite
  sides (6830 cd).
Cameras: "courtyard" (from the ground arcade's north-west corner across the courtyard) and
"gallery" (along the upper gallery's east side).

Run from anywhere (optional: another output path, and --subdivide N to cut every untextured
quad into N x N for benchmarks):
    /usr/bin/python3 content/atrium/make_atrium.py [OUT.gltf] [--subdivide N]
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import gltf_writer  # noqa: E402
from gltf_writer import GltfWriter, normalize, rotation_looking_along  # noqa: E402

COURT = 4.0        # courtyard half-width, m
OUTER = 7.0        # inner face of the outer walls, m
WALL = 0.3         # outer wall thickness, m
STOREY = 3.5       # upper gallery floor, m
SLAB = 0.25        # slab thickness, m
ROOF = 7.0         # underside of the roof slab, m
COLUMN = 0.35      # column side, m
LINTEL = 0.5       # lintel depth under each slab, m
PARAPET = 1.0      # upper gallery parapet height, m
SUN_DIRECTION = normalize([0.42, -0.85, -0.32])  # where the sunlight travels (58 deg down)
SUN_W_PER_M2 = 12.0
SUN_COLOR = [1.0, 0.93, 0.82]
LANTERN_W_PER_SR = 10.0
LANTERN_COLOR = [1.0, 0.8, 0.55]
TEXTURE_REPEAT = 2.0  # metres per texture repeat

SUBDIVIDE = 1


def quad(a, b, c, d):
    """Triangles of the quad a b c d, cut into SUBDIVIDE x SUBDIVIDE (--subdivide)."""
    return gltf_writer.subdivided_quad(a, b, c, d, SUBDIVIDE)


def box(lo, hi):
    return gltf_writer.box(lo, hi, quad)


def plain_box(lo, hi):
    """A box of whole quads (textured surfaces keep their texture coordinates simple)."""
    return gltf_writer.box(lo, hi)


def planar_uvs(triangles):
    """Texture coordinates per corner: the two world axes across each triangle's dominant
    normal axis, one repeat every TEXTURE_REPEAT metres."""
    uvs = []
    for tri in triangles:
        n = gltf_writer.triangle_normal(tri)
        axis = max(range(3), key=lambda k: abs(n[k]))
        u, v = [k for k in range(3) if k != axis]
        uvs.append([[p[u] / TEXTURE_REPEAT, p[v] / TEXTURE_REPEAT] for p in tri])
    return uvs


def tile_rows():
    """64 x 64 sRGB texels: 2 x 2 stone tiles of two greys with dark grout lines."""
    light, dark, grout = (190, 182, 168), (150, 142, 130), (70, 66, 60)
    rows = []
    for y in range(64):
        row = []
        for x in range(64):
            if x % 32 < 2 or y % 32 < 2:
                row.append(grout)
            else:
                row.append(light if (x // 32 + y // 32) % 2 == 0 else dark)
        rows.append(row)
    return rows


def plaster_rows():
    """64 x 64 sRGB texels: warm plaster with faint horizontal courses (deterministic)."""
    rows = []
    for y in range(64):
        course = 0.92 if y % 16 == 0 else 1.0
        row = []
        for x in range(64):
            grain = 0.96 + 0.04 * math.sin(0.9 * x + 2.3 * y) * math.cos(0.31 * x * y)
            row.append(tuple(int(c * course * grain) for c in (214, 190, 160)))
        rows.append(row)
    return rows


def ring(y0, y1, inner, outer):
    """Four boxes covering the square ring inner <= max(|x|, |z|) <= outer between y0 and y1."""
    return (box([-outer, y0, -outer], [outer, y1, -inner]) + box([-outer, y0, inner], [outer, y1, outer]) +
            box([-outer, y0, -inner], [-inner, y1, inner]) + box([inner, y0, -inner], [outer, y1, inner]))


def column_positions():
    """Column centres along the courtyard's edge, every 2 m, corners included."""
    steps = [-COURT + 2.0 * i for i in range(int(2 * COURT / 2.0) + 1)]
    points = set()
    for s in steps:
        for edge in (-COURT, COURT):
            points.add((s, edge))
            points.add((edge, s))
    return sorted(points)


def main():
    global SUBDIVIDE
    args = sys.argv[1:]
    SUBDIVIDE = gltf_writer.take_subdivide(args)
    out = args[0] if args else os.path.join(os.path.dirname(os.path.abspath(__file__)), "atrium.gltf")
    gltf = GltfWriter("bounce content/atrium/make_atrium.py")
    stone = gltf.material("stone_floor", (1.0, 1.0, 1.0),
                          base_color_texture=gltf.png_texture("tiles", 64, 64, tile_rows()))
    plaster = gltf.material("plaster", (1.0, 1.0, 1.0),
                            base_color_texture=gltf.png_texture("plaster", 64, 64, plaster_rows()))
    limestone = gltf.material("limestone", (0.70, 0.66, 0.58))
    slab = gltf.material("slab", (0.75, 0.74, 0.72))
    wood = gltf.material("gallery_floor", (0.42, 0.30, 0.20))

    def add(name, triangles, material, uvs=None):
        gltf.node({"name": name, "mesh": gltf.mesh(name, triangles, material, corner_uvs=uvs)})

    o, w, c = OUTER, WALL, COURT
    # The ground: one slab under everything; its top is the courtyard's and the arcade's floor.
    ground = plain_box([-o - w, -SLAB, -o - w], [o + w, 0.0, o + w])
    add("ground", ground, stone, planar_uvs(ground))
    # Outer walls, full height, plaster inside and out.
    top = ROOF + SLAB
    walls = (plain_box([-o - w, 0, -o - w], [o + w, top, -o]) + plain_box([-o - w, 0, o], [o + w, top, o + w]) +
             plain_box([-o - w, 0, -o], [-o, top, o]) + plain_box([o, 0, -o], [o + w, top, o]))
    add("outer_walls", walls, plaster, planar_uvs(walls))
    # The gallery floor slab and the roof slab, each a ring over the galleries.
    add("gallery_slab", ring(STOREY, STOREY + SLAB, c - COLUMN / 2, o), slab)
    add("roof", ring(ROOF, top, c - COLUMN / 2, o), slab)
    # Lintels under each slab along the courtyard edge (the arcade's openings' heads).
    half = COLUMN / 2
    add("lintels", ring(STOREY - LINTEL, STOREY, c - half, c + half) +
        ring(ROOF - LINTEL, ROOF, c - half, c + half), limestone)
    # Columns on both storeys, and the upper parapet between the upper columns.
    columns = []
    for x, z in column_positions():
        columns += box([x - half, 0.0, z - half], [x + half, STOREY - LINTEL, z + half])
        columns += box([x - half, STOREY + SLAB, z - half], [x + half, ROOF - LINTEL, z + half])
    add("columns", columns, limestone)
    add("parapet", ring(STOREY + SLAB, STOREY + SLAB + PARAPET, c - 0.08, c + 0.08), limestone)
    # The upper gallery's floor finish, 2 cm of wood on the slab.
    add("gallery_floor", ring(STOREY + SLAB, STOREY + SLAB + 0.02, c + 0.08, o), wood)

    gltf.use("KHR_lights_punctual")
    lights = [{"name": "sun", "type": "directional", "color": SUN_COLOR,
               "intensity": SUN_W_PER_M2 * 683.0}]
    lanterns = [("lantern_west", [-5.5, 2.6, 1.0]), ("lantern_east", [5.5, 2.6, -1.0])]
    for name, _ in lanterns:
        lights.append({"name": name, "type": "point", "color": LANTERN_COLOR,
                       "intensity": LANTERN_W_PER_SR * 683.0})
    gltf.doc["extensions"] = {"KHR_lights_punctual": {"lights": lights}}
    gltf.node({"name": "sun", "rotation": rotation_looking_along(SUN_DIRECTION),
               "extensions": {"KHR_lights_punctual": {"light": 0}}})
    for index, (name, position) in enumerate(lanterns, start=1):
        gltf.node({"name": name, "translation": position,
                   "extensions": {"KHR_lights_punctual": {"light": index}}})
    gltf.cameras([("courtyard", [-6.3, 1.6, 6.3], [2.0, 2.8, -3.0]),
                  ("gallery", [6.1, 5.0, -6.2], [5.6, 4.3, 5.0])], 70.0, 16 / 9, 100.0)
    gltf.write(out)


if __name__ == "__main__":
    main()
