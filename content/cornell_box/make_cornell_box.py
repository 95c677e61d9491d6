#!/usr/bin/python3
"""Writes cornell_box.gltf from Cornell's published measurements (standard library only).

Run from anywhere (optional argument: another output path):
    /usr/bin/python3 content/cornell_box/make_cornell_box.py
Sources and conversions are recorded in content/README.md.
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from gltf_writer import GltfWriter, cross, dot, sub, triangle_normal  # noqa: E402

LUMENS_PER_WATT = 683.0  # engine/scene/units.h: W/(sr·m²) = nit / 683
MM = 0.001               # the data page is in millimetres; bounce uses metres

# "Cornell Box Data" page, Cornell University Program of Computer Graphics
# (www.graphics.cornell.edu/online/box/data.html), vertices in mm, as listed there.
FLOOR = [(552.8, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, 559.2), (549.6, 0.0, 559.2)]
LIGHT = [(343.0, 548.8, 227.0), (343.0, 548.8, 332.0), (213.0, 548.8, 332.0), (213.0, 548.8, 227.0)]
CEILING = [(556.0, 548.8, 0.0), (556.0, 548.8, 559.2), (0.0, 548.8, 559.2), (0.0, 548.8, 0.0)]
BACK_WALL = [(549.6, 0.0, 559.2), (0.0, 0.0, 559.2), (0.0, 548.8, 559.2), (556.0, 548.8, 559.2)]
RIGHT_WALL = [(0.0, 0.0, 559.2), (0.0, 0.0, 0.0), (0.0, 548.8, 0.0), (0.0, 548.8, 559.2)]  # green
LEFT_WALL = [(552.8, 0.0, 0.0), (549.6, 0.0, 559.2), (556.0, 548.8, 559.2), (556.0, 548.8, 0.0)]  # red
SHORT_BLOCK = [
    [(130.0, 165.0, 65.0), (82.0, 165.0, 225.0), (240.0, 165.0, 272.0), (290.0, 165.0, 114.0)],
    [(290.0, 0.0, 114.0), (290.0, 165.0, 114.0), (240.0, 165.0, 272.0), (240.0, 0.0, 272.0)],
    [(130.0, 0.0, 65.0), (130.0, 165.0, 65.0), (290.0, 165.0, 114.0), (290.0, 0.0, 114.0)],
    [(82.0, 0.0, 225.0), (82.0, 165.0, 225.0), (130.0, 165.0, 65.0), (130.0, 0.0, 65.0)],
    [(240.0, 0.0, 272.0), (240.0, 165.0, 272.0), (82.0, 165.0, 225.0), (82.0, 0.0, 225.0)],
]
TALL_BLOCK = [
    [(423.0, 330.0, 247.0), (265.0, 330.0, 296.0), (314.0, 330.0, 456.0), (472.0, 330.0, 406.0)],
    [(423.0, 0.0, 247.0), (423.0, 330.0, 247.0), (472.0, 330.0, 406.0), (472.0, 0.0, 406.0)],
    [(472.0, 0.0, 406.0), (472.0, 330.0, 406.0), (314.0, 330.0, 456.0), (314.0, 0.0, 456.0)],
    [(314.0, 0.0, 456.0), (314.0, 330.0, 456.0), (265.0, 330.0, 296.0), (265.0, 0.0, 296.0)],
    [(265.0, 0.0, 296.0), (265.0, 330.0, 296.0), (423.0, 330.0, 247.0), (423.0, 0.0, 247.0)],
]
# Camera (same page): position (278, 273, -800) mm, looking along +z, up +y, focal length
# 35 mm, film 25 mm × 25 mm.
CAMERA_POSITION = (278.0, 273.0, -800.0)
FOCAL_MM, FILM_MM = 35.0, 25.0
LIGHT_DROP_MM = 0.1  # the light sits this far below the ceiling so the two never coincide

# Diffuse reflectances (linear RGB), as used by McGuire's CornellBox-Original.mtl and most
# RGB renditions of the box: an RGB reduction of Cornell's measured spectral reflectances.
WHITE = (0.725, 0.71, 0.68)
RED = (0.63, 0.065, 0.05)
GREEN = (0.14, 0.45, 0.091)
LIGHT_ALBEDO = (0.78, 0.78, 0.78)  # McGuire's `light` Kd
LIGHT_RADIANCE = (17.0, 12.0, 4.0)  # W/(sr·m²), McGuire's `light` Ke


def metres(points):
    return [[c * MM for c in p] for p in points]


def quad_triangles(quad, facing):
    """Two triangles of the quad, wound so their normals point along `facing(centroid)`."""
    tris = [[quad[0], quad[1], quad[2]], [quad[0], quad[2], quad[3]]]
    out = []
    for tri in tris:
        centroid = [sum(p[i] for p in tri) / 3 for i in range(3)]
        if dot(triangle_normal(tri), facing(centroid)) < 0:
            tri = [tri[0], tri[2], tri[1]]
        assert dot(triangle_normal(tri), facing(centroid)) > 0
        out.append(tri)
    return out


def build(generator):
    """The Cornell box (room, light, blocks, camera) in a GltfWriter, ready to extend."""
    room_centre = [278.0 * MM, 274.4 * MM, 279.6 * MM]
    inward = lambda c: sub(room_centre, c)  # noqa: E731  room surfaces face the interior
    down = lambda c: [0.0, -1.0, 0.0]       # noqa: E731

    gltf = GltfWriter(generator)
    white = gltf.material("white", WHITE)
    red = gltf.material("red", RED)
    green = gltf.material("green", GREEN)
    # Emission = emissiveFactor × emissiveStrength nits; factor = radiance / max, strength =
    # max × 683, so the loader's nit/683 gives back exactly (17, 12, 4) W/(sr·m²).
    peak = max(LIGHT_RADIANCE)
    light = gltf.material("light", LIGHT_ALBEDO,
                          emissive_factor=[c / peak for c in LIGHT_RADIANCE],
                          emissive_strength=peak * LUMENS_PER_WATT)

    def add(name, quads, material, facing):
        tris = [t for q in quads for t in quad_triangles(metres(q), facing)]
        gltf.node({"name": name, "mesh": gltf.mesh(name, tris, material)})

    add("floor", [FLOOR], white, inward)
    add("ceiling", [CEILING], white, inward)
    add("back_wall", [BACK_WALL], white, inward)
    add("right_wall", [RIGHT_WALL], green, inward)
    add("left_wall", [LEFT_WALL], red, inward)
    lowered = [(x, y - LIGHT_DROP_MM, z) for (x, y, z) in LIGHT]
    add("light", [lowered], light, down)
    for name, block in (("short_block", SHORT_BLOCK), ("tall_block", TALL_BLOCK)):
        corners = metres([p for q in block for p in q])
        centre = [sum(p[i] for p in corners) / len(corners) for i in range(3)]
        centre[1] = 0.0  # blocks stand on the floor; faces point away from their axis
        outward = lambda c, centre=centre: sub(c, centre)  # noqa: E731
        add(name, block, white, outward)

    yfov = 2.0 * math.atan(0.5 * FILM_MM / FOCAL_MM)
    gltf.doc["cameras"] = [{"name": "cornell", "type": "perspective", "perspective": {
        "yfov": yfov, "aspectRatio": 1.0, "znear": 0.01, "zfar": 100.0}}]
    # glTF cameras look along local −Z with +Y up: a half turn about +Y looks along world +Z,
    # which puts world +x (the red wall) on the image's left.
    gltf.node({"name": "camera", "camera": 0, "rotation": [0.0, 1.0, 0.0, 0.0],
               "translation": [c * MM for c in CAMERA_POSITION]})
    return gltf


def main():
    out_dir = os.path.dirname(os.path.abspath(__file__))
    gltf = build("bounce content/cornell_box/make_cornell_box.py")
    gltf.write(sys.argv[1] if len(sys.argv) > 1 else os.path.join(out_dir, "cornell_box.gltf"))


if __name__ == "__main__":
    main()
