#!/usr/bin/python3
"""Writes vpl_corner.gltf: a concave box corner for the VPL clamp at its singularity
(standard library only).

Three 0.5 m squares meet at the origin: a floor (y = 0, facing +y, white), a red wall (x = 0,
facing +x) and a green wall (z = 0, facing +z), 0.4 m high; the other sides are open. A white
point light of 1 W/sr (683 cd) at (0.3, 0.3, 0.3) m lights all three. Every point of the three
inner faces sees every other (they bound a convex region), so VPL light here has no visibility
error: what separates it from the path tracer is VPL noise and the clamp, which matters where a
VPL on one face sits millimetres from a receiver on another, along the two walls' foot and the
vertical edge. No camera: the test frames the corner with a .json wrapper.

Run from anywhere (optional argument: another output path):
    /usr/bin/python3 content/vpl_corner/make_vpl_corner.py
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from gltf_writer import GltfWriter, dot, triangle_normal  # noqa: E402

SIZE = 0.5              # m, edge of the floor and width of the walls
HEIGHT = 0.4            # m, walls
LIGHT_POSITION = [0.3, 0.3, 0.3]  # m
LIGHT_CANDELA = 683.0   # cd → 1 W/sr (engine/scene/units.h)
WHITE = (0.725, 0.71, 0.68)  # the Cornell box's reflectances (content/README.md)
RED = (0.63, 0.065, 0.05)
GREEN = (0.14, 0.45, 0.091)


def quad(corners, facing):
    """Two triangles of the quad, wound so their normals point along `facing`."""
    out = []
    for tri in ([corners[0], corners[1], corners[2]], [corners[0], corners[2], corners[3]]):
        if dot(triangle_normal(tri), facing) < 0:
            tri = [tri[0], tri[2], tri[1]]
        assert dot(triangle_normal(tri), facing) > 0
        out.append(tri)
    return out


def main():
    out_dir = os.path.dirname(os.path.abspath(__file__))
    gltf = GltfWriter("bounce content/vpl_corner/make_vpl_corner.py")
    s, h = SIZE, HEIGHT
    faces = [
        ("floor", WHITE, [[0, 0, 0], [s, 0, 0], [s, 0, s], [0, 0, s]], [0, 1, 0]),
        ("red_wall", RED, [[0, 0, 0], [0, h, 0], [0, h, s], [0, 0, s]], [1, 0, 0]),
        ("green_wall", GREEN, [[0, 0, 0], [s, 0, 0], [s, h, 0], [0, h, 0]], [0, 0, 1]),
    ]
    for name, colour, corners, facing in faces:
        material = gltf.material(name, colour)
        gltf.node({"name": name, "mesh": gltf.mesh(name, quad(corners, facing), material)})
    gltf.use("KHR_lights_punctual")
    gltf.doc["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"name": "point", "type": "point", "color": [1.0, 1.0, 1.0], "intensity": LIGHT_CANDELA}]}}
    gltf.node({"name": "point_light", "translation": LIGHT_POSITION,
               "extensions": {"KHR_lights_punctual": {"light": 0}}})
    gltf.write(sys.argv[1] if len(sys.argv) > 1 else os.path.join(out_dir, "vpl_corner.gltf"))


if __name__ == "__main__":
    main()
