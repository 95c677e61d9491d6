#!/usr/bin/python3
"""Writes many_lights.gltf: a scene for the light sampler (standard library only).

A 12 m × 3 m × 12 m room (walls ρ = 0.6, floor ρ = 0.5, both grey) lit by 64 point lights on
an 8 × 8 grid 2.6 m above the floor whose intensities spread over 100× (1.5 to 150 W/sr...
in candela: 683 cd = 1 W/sr, engine/scene/units.h) with varied colours, plus a warm 1 m²
ceiling emitter. A camera at 1.6 m in one corner looks across the room. Fixed pseudo-random
values (a linear congruential generator), so the file is reproducible.

Run from anywhere (optional argument: another output path):
    /usr/bin/python3 content/many_lights/make_many_lights.py
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from gltf_writer import GltfWriter  # noqa: E402

HALF = 6.0      # m, half the room's width and depth
HEIGHT = 3.0    # m
GRID = 8
LIGHT_Y = 2.6   # m


def lcg(state):
    state = (1103515245 * state + 12345) % (1 << 31)
    return state, state / float(1 << 31)


def quad(a, b, c, d):
    return [[a, b, c], [a, c, d]]


def main():
    out_dir = os.path.dirname(os.path.abspath(__file__))
    gltf = GltfWriter("bounce content/many_lights/make_many_lights.py")
    wall = gltf.material("wall", (0.6, 0.6, 0.6))
    floor = gltf.material("floor", (0.5, 0.5, 0.5))
    lamp = gltf.material("lamp", (0.0, 0.0, 0.0), emissive_factor=(1.0, 0.8, 0.6),
                         emissive_strength=5.0)
    s, h = HALF, HEIGHT
    # Faces listed counter-clockwise as seen from inside the room.
    gltf.node({"name": "floor", "mesh": gltf.mesh("floor", quad(
        [-s, 0, -s], [-s, 0, s], [s, 0, s], [s, 0, -s]), floor)})
    walls = (quad([-s, h, -s], [s, h, -s], [s, h, s], [-s, h, s]) +      # ceiling, faces -y
             quad([-s, 0, -s], [s, 0, -s], [s, h, -s], [-s, h, -s]) +     # z = -s, faces +z
             quad([-s, 0, s], [-s, h, s], [s, h, s], [s, 0, s]) +         # z = +s, faces -z
             quad([-s, 0, -s], [-s, h, -s], [-s, h, s], [-s, 0, s]) +     # x = -s, faces +x
             quad([s, 0, -s], [s, 0, s], [s, h, s], [s, h, -s]))          # x = +s, faces -x
    gltf.node({"name": "walls", "mesh": gltf.mesh("walls", walls, wall)})
    y = h - 0.01
    gltf.node({"name": "lamp", "mesh": gltf.mesh("lamp", quad(
        [2.0, y, 2.0], [3.0, y, 2.0], [3.0, y, 3.0], [2.0, y, 3.0]), lamp)})

    lights, state = [], 12345
    for i in range(GRID * GRID):
        state, u = lcg(state)
        state, r = lcg(state)
        state, g = lcg(state)
        candela = 683.0 * 1.5 * math.pow(100.0, u)  # 1.5 .. 150 W/sr, log-uniform
        lights.append({"name": "point%d" % i, "type": "point",
                       "color": [0.4 + 0.6 * r, 0.4 + 0.6 * g, 0.7], "intensity": candela})
    gltf.use("KHR_lights_punctual")
    gltf.doc["extensions"] = {"KHR_lights_punctual": {"lights": lights}}
    step = 2 * s / GRID
    for i in range(GRID * GRID):
        x = -s + step * (i % GRID + 0.5)
        z = -s + step * (i // GRID + 0.5)
        gltf.node({"name": "light%d" % i, "translation": [x, LIGHT_Y, z],
                   "extensions": {"KHR_lights_punctual": {"light": i}}})
    gltf.doc["cameras"] = [{"name": "corner", "type": "perspective", "perspective": {
        "yfov": math.radians(60.0), "aspectRatio": 1.5, "znear": 0.01, "zfar": 100.0}}]
    # Yaw −135° about +y: the camera's −Z looks towards (+x, +z), the room's far corner.
    a = math.radians(-135.0) / 2.0
    gltf.node({"name": "camera", "camera": 0, "rotation": [0.0, math.sin(a), 0.0, math.cos(a)],
               "translation": [-s + 0.5, 1.6, -s + 0.5]})
    gltf.write(sys.argv[1] if len(sys.argv) > 1 else os.path.join(out_dir, "many_lights.gltf"))


if __name__ == "__main__":
    main()
