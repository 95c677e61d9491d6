#!/usr/bin/python3
"""Writes sunlit_room.gltf: an interior that stresses a lightmapper (standard library only).

Two rooms side by side under one floor slab and one ceiling slab (each a 10 cm box that runs
under and over every wall), lit only by the sun through one window, so almost everything seen
is indirect light:
- room A, 4 m x 3 m x 2.6 m, with the window (1.8 m x 1.3 m) in its south wall; the sun's patch
  falls on a textured rug and a table (legs 4 cm thin) stands in it;
- a 5 cm partition wall with a door (0.9 m x 2.05 m) and a door frame that overlaps the wall;
- room B, 2 m x 3 m, lit only through the door, with a cabinet.
Exterior walls are 10 cm boxes. The rug's base colour is a 64 x 64 PNG (stripes of two sRGB
colours and a border) embedded in the file. Sun: a directional light of 12 W/m^2 per channel
at (1, 0.92, 0.8) times that, i.e. 8196 lux (683 lux = 1 W/m^2, engine/scene/units.h), coming
down at about 33 degrees through the window. Cameras: "room" (room A from its north-west
corner, the door on the left) and "next_room" (room B from its south-east corner, looking at the
partition and the door).

Run from anywhere (optional arguments: another output path, and --subdivide N to cut every
quad but the rug's into N x N, the same scene in N^2 times the triangles, for benchmarks):
    /usr/bin/python3 content/sunlit_room/make_sunlit_room.py [OUT.gltf] [--subdivide N]
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import gltf_writer  # noqa: E402
from gltf_writer import GltfWriter, normalize, rotation_looking_along  # noqa: E402

HEIGHT = 2.6          # m, floor to ceiling
ROOM_A = (0.0, 4.0)   # x extent of room A, m
WALL_B = (4.0, 4.05)  # the partition, 5 cm
ROOM_B = (4.05, 6.05)
DEPTH = 3.0           # z extent of both rooms, m
EXTERIOR = 0.1        # exterior walls and slabs, m
WINDOW = ((1.0, 2.8), (0.8, 2.1))   # x and y of the window in the south wall (z = DEPTH)
DOOR = ((1.2, 2.1), 2.05)           # z extent and height of the door in the partition
SUN_DIRECTION = normalize([0.25, -0.55, -0.76])  # where the sunlight travels
SUN_W_PER_M2 = 12.0
SUN_COLOR = [1.0, 0.92, 0.8]


SUBDIVIDE = 1  # quads cut into SUBDIVIDE x SUBDIVIDE (--subdivide)


def quad(a, b, c, d):
    """Triangles of the quad a b c d, cut into SUBDIVIDE x SUBDIVIDE (--subdivide)."""
    return gltf_writer.subdivided_quad(a, b, c, d, SUBDIVIDE)


def box(lo, hi):
    """A closed box of this scene's (subdivided) quads, every face wound outwards."""
    return gltf_writer.box(lo, hi, quad)


def rug_rows():
    """64 x 64 sRGB texels: a cream border 4 texels wide around red and cream stripes."""
    red, cream, border = (150, 40, 35), (220, 200, 160), (60, 70, 110)
    rows = []
    for y in range(64):
        row = []
        for x in range(64):
            if min(x, y, 63 - x, 63 - y) < 4:
                row.append(border)
            else:
                row.append(red if (x // 6) % 2 == 0 else cream)
        rows.append(row)
    return rows


def main():
    global SUBDIVIDE
    args = sys.argv[1:]
    SUBDIVIDE = gltf_writer.take_subdivide(args)
    out = args[0] if args else os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                            "sunlit_room.gltf")
    gltf = GltfWriter("bounce content/sunlit_room/make_sunlit_room.py")
    wall = gltf.material("wall", (0.75, 0.73, 0.70))
    slab = gltf.material("ceiling", (0.80, 0.80, 0.80))
    wood = gltf.material("floor", (0.45, 0.32, 0.20))
    frame = gltf.material("door_frame", (0.85, 0.85, 0.85))
    table = gltf.material("table", (0.35, 0.22, 0.12))
    cabinet = gltf.material("cabinet", (0.30, 0.40, 0.55))
    book = gltf.material("book", (0.60, 0.10, 0.10))
    rug = gltf.material("rug", (1.0, 1.0, 1.0),
                        base_color_texture=gltf.png_texture("rug", 64, 64, rug_rows()))

    def add(name, triangles, material, uvs=None):
        gltf.node({"name": name, "mesh": gltf.mesh(name, triangles, material, corner_uvs=uvs)})

    e, h, d = EXTERIOR, HEIGHT, DEPTH
    x0, x1 = ROOM_A[0] - e, ROOM_B[1] + e
    # Slabs under and over both rooms and every wall.
    add("floor", box([x0, -e, -e], [x1, 0.0, d + e]), wood)
    add("ceiling", box([x0, h, -e], [x1, h + e, d + e]), slab)
    # Exterior walls; the south one around the window.
    (wx0, wx1), (wy0, wy1) = WINDOW
    exterior = (box([x0, 0, -e], [ROOM_A[0], h, d + e]) + box([ROOM_B[1], 0, -e], [x1, h, d + e]) +
                box([ROOM_A[0], 0, -e], [ROOM_B[1], h, 0.0]) +
                box([ROOM_A[0], 0, d], [wx0, h, d + e]) + box([wx1, 0, d], [ROOM_B[1], h, d + e]) +
                box([wx0, 0, d], [wx1, wy0, d + e]) + box([wx0, wy1, d], [wx1, h, d + e]))
    add("exterior_walls", exterior, wall)
    # The partition with its door, and the frame that overlaps it by 2 cm on each side.
    (dz0, dz1), dh = DOOR
    bx0, bx1 = WALL_B
    add("partition", box([bx0, 0, 0], [bx1, h, dz0]) + box([bx0, 0, dz1], [bx1, h, d]) +
        box([bx0, dh, dz0], [bx1, h, dz1]), wall)
    f = 0.04
    add("door_frame", box([bx0 - 0.02, 0, dz0 - f], [bx1 + 0.02, dh + f, dz0]) +
        box([bx0 - 0.02, 0, dz1], [bx1 + 0.02, dh + f, dz1 + f]) +
        box([bx0 - 0.02, dh, dz0], [bx1 + 0.02, dh + f, dz1]), frame)
    # A table in the sun's patch: a 4 cm top on four 4 cm legs, a book on it.
    tx0, tx1, tz0, tz1, ty = 2.4, 3.6, 0.25, 0.95, 0.72
    legs = []
    for lx in (tx0 + 0.03, tx1 - 0.07):
        for lz in (tz0 + 0.03, tz1 - 0.07):
            legs += box([lx, 0, lz], [lx + 0.04, ty, lz + 0.04])
    add("table", box([tx0, ty, tz0], [tx1, ty + 0.04, tz1]) + legs, table)
    add("book", box([2.8, ty + 0.04, 0.45], [3.1, ty + 0.08, 0.66]), book)
    # The rug: one textured quad 5 mm over the floor, facing up, its stripes along x.
    rx0, rx1, rz0, rz1, ry = 1.2, 3.0, 1.0, 2.2, 0.005
    a, b, c, d = [rx0, ry, rz0], [rx0, ry, rz1], [rx1, ry, rz1], [rx1, ry, rz0]
    add("rug", [[a, b, c], [a, c, d]], rug,
        uvs=[[[0, 0], [0, 1], [1, 1]], [[0, 0], [1, 1], [1, 0]]])
    # Room B's cabinet against its east wall.
    add("cabinet", box([ROOM_B[1] - 0.45, 0, 0.3], [ROOM_B[1], 1.8, 1.4]), cabinet)

    gltf.use("KHR_lights_punctual")
    gltf.doc["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"name": "sun", "type": "directional", "color": SUN_COLOR,
         "intensity": SUN_W_PER_M2 * 683.0}]}}
    gltf.node({"name": "sun", "rotation": rotation_looking_along(SUN_DIRECTION),
               "extensions": {"KHR_lights_punctual": {"light": 0}}})
    gltf.cameras([("room", [0.35, 1.55, 0.35], [3.5, 0.7, 2.3]),
                  ("next_room", [5.75, 1.5, 2.75], [4.0, 0.5, 1.0])], 70.0, 1.5, 50.0)
    gltf.write(out)


if __name__ == "__main__":
    main()
