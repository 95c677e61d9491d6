#!/usr/bin/python3
"""Writes cornell_box_dynamic.gltf: the Cornell box of ../cornell_box (same generator) plus a
white sphere in a node marked dynamic (extras.bounce.mobility = "dynamic"), for the VPL term on
dynamic objects (standard library only).

Run from anywhere (optional argument: another output path):
    /usr/bin/python3 content/cornell_box_dynamic/make_cornell_box_dynamic.py
The box's sources are recorded in content/README.md.
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, ".."))
sys.path.insert(0, os.path.join(HERE, "..", "cornell_box"))
import make_cornell_box  # noqa: E402

SPHERE_NAME = "sphere"
SPHERE_RADIUS = 0.1  # m: 0.18 of the box's 0.55 m
# Where the file puts it (m): over the floor's centre, clear of both blocks (the short block's
# top is at y = 0.165 m); bounce-render/bounce-trace --move and bounce-view place it elsewhere.
SPHERE_POSITION = (0.278, 0.28, 0.12)
SPHERE_ALBEDO = (0.8, 0.8, 0.8)  # white-ish, so the walls' red and green show on it
STACKS, SLICES = 24, 48  # 2 × 48 × 23 = 2208 triangles: round at any frame size we draw


def sphere_triangles(radius):
    """Triangles (counter-clockwise seen from outside) and their corners' unit normals."""
    def point(i, j):
        theta = math.pi * i / STACKS  # from +y down
        phi = 2.0 * math.pi * j / SLICES
        n = [math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi)]
        return [radius * c for c in n], n

    tris, normals = [], []
    for i in range(STACKS):
        for j in range(SLICES):
            (a, na), (b, nb) = point(i, j), point(i + 1, j)
            (c, nc), (d, nd) = point(i + 1, j + 1), point(i, j + 1)
            if i > 0:  # no degenerate triangle at the poles
                tris.append([a, b, d])
                normals.append([na, nb, nd])
            if i < STACKS - 1:
                tris.append([b, c, d])
                normals.append([nb, nc, nd])
    # Each face's geometric normal points outwards (same side as its corners' normals).
    for tri, ns in zip(tris, normals):
        centre = [sum(p[k] for p in tri) / 3 for k in range(3)]
        assert make_cornell_box.dot(make_cornell_box.triangle_normal(tri), centre) > 0
    return tris, normals


def main():
    gltf = make_cornell_box.build(
        "bounce content/cornell_box_dynamic/make_cornell_box_dynamic.py")
    material = gltf.material("sphere_white", SPHERE_ALBEDO)
    tris, normals = sphere_triangles(SPHERE_RADIUS)
    mesh = gltf.mesh(SPHERE_NAME, tris, material, corner_normals=normals)
    gltf.node({"name": SPHERE_NAME, "mesh": mesh, "translation": list(SPHERE_POSITION),
               "extras": {"bounce": {"mobility": "dynamic"}}})
    gltf.write(sys.argv[1] if len(sys.argv) > 1
               else os.path.join(HERE, "cornell_box_dynamic.gltf"))


if __name__ == "__main__":
    main()
