#!/usr/bin/python3
"""Writes panels_over_rails.gltf: 64 small area lights over thin casters (standard library only).

Where shadow maps fail: a 4 m x 4 m floor (rho 0.7) under 64 emissive panels, 0.16 m square,
1.2 m up on an 8 x 8 grid 0.45 m apart, facing down, written as ONE emissive mesh (as exporters
write a fixture's panels; the renderer cuts it into 64 lights by shape), one of them tilted 20
degrees; under them a grating of 2 cm metal rails (rho 0.5) 0.3 m up and 0.4 m apart each way,
and eight 3 cm posts. Emission (8, 7, 6) W/(sr m^2): emissiveFactor (1, 0.875, 0.75) at 8 x 683
nits (engine/scene/units.h). Camera "over_the_rails" at 0.95 m looks down across the floor,
yfov 60 degrees, aspect 16:9.

Run from anywhere (optional argument: another output path):
    /usr/bin/python3 content/panels_over_rails/make_panels_over_rails.py
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from gltf_writer import (GltfWriter, box, normalize, quad, rotation_looking_along,  # noqa: E402
                         sub, triangle_normal)

HALF = 2.0          # m, half the floor's side
PANEL = 0.16        # m
PANEL_Y = 1.2       # m
GRID, PITCH = 8, 0.45
RADIANCE = (8.0, 7.0, 6.0)  # W/(sr m^2)
RAIL_Y, RAIL, RAIL_PITCH = 0.3, 0.02, 0.4


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "panels_over_rails.gltf")
    gltf = GltfWriter("bounce content/panels_over_rails/make_panels_over_rails.py")
    floor = gltf.material("floor", (0.7, 0.7, 0.7))
    metal = gltf.material("metal", (0.5, 0.5, 0.5))
    peak = max(RADIANCE)
    glow = gltf.material("glow", (0.0, 0.0, 0.0), emissive_factor=[c / peak for c in RADIANCE],
                         emissive_strength=peak * 683.0)
    h = HALF
    gltf.node({"name": "floor", "mesh": gltf.mesh("floor", quad(
        [-h, 0, -h], [-h, 0, h], [h, 0, h], [h, 0, -h]), floor)})
    panels = []
    for i in range(GRID):
        for j in range(GRID):
            x = -PITCH * (GRID - 1) / 2 + PITCH * i - PANEL / 2
            z = -PITCH * (GRID - 1) / 2 + PITCH * j - PANEL / 2
            c = [x, PANEL_Y, z]
            u, v = [PANEL, 0.0, 0.0], [0.0, 0.0, PANEL]  # u x v = -y: facing down
            if i == GRID - 1 and j == 0:  # one tilted 20 degrees about z
                a = math.radians(20.0)
                u = [PANEL * math.cos(a), PANEL * math.sin(a), 0.0]
            p = [[c[k] + s * u[k] + t * v[k] for k in range(3)]
                 for s, t in ((0, 0), (1, 0), (1, 1), (0, 1))]
            tris = quad(*p)
            assert all(triangle_normal(t)[1] < 0 for t in tris)
            panels += tris
    gltf.node({"name": "panels", "mesh": gltf.mesh("panels", panels, glow)})
    rails = []
    n = int(round(2 * h / RAIL_PITCH))
    for k in range(n):
        at = -h + RAIL_PITCH * (k + 0.5)
        r = RAIL / 2
        rails += box([-h, RAIL_Y - r, at - r], [h, RAIL_Y + r, at + r])
        rails += box([at - r, RAIL_Y + r, -h], [at + r, RAIL_Y + 3 * r, h])
    for px, pz in ((0.4, 0.4), (-0.6, 0.5), (0.55, -0.6), (-0.5, -0.55),
                   (1.3, 1.1), (-1.4, 1.2), (1.2, -1.3), (-1.1, -1.4)):
        rails += box([px - 0.015, 0.0, pz - 0.015], [px + 0.015, RAIL_Y - RAIL / 2, pz + 0.015])
    gltf.node({"name": "grating", "mesh": gltf.mesh("grating", rails, metal)})
    gltf.doc["cameras"] = [{"name": "over_the_rails", "type": "perspective", "perspective": {
        "yfov": math.radians(60.0), "aspectRatio": 16.0 / 9.0, "znear": 0.01, "zfar": 50.0}}]
    eye, target = [-1.9, 0.95, 2.3], [0.3, 0.0, -0.5]
    gltf.node({"name": "over_the_rails", "camera": 0,
               "rotation": rotation_looking_along(normalize(sub(target, eye))),
               "translation": eye})
    gltf.write(out)


if __name__ == "__main__":
    main()
