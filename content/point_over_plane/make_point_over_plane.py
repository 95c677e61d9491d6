#!/usr/bin/python3
"""Writes point_over_plane.gltf: an analytic test scene (standard library only).

A 4 m × 4 m Lambertian plane (ρ = 0.5) at y = 0 facing +y; a white point light of 683 cd
(= 1 W/sr, engine/scene/units.h) at height h = 1 m above its centre; a camera 3 m above the
centre looking straight down. Irradiance at a floor point at horizontal distance r:
E(r) = I·h / (h² + r²)^(3/2) W/m², radiance L = ρ/π · E (1/(2π) W/(sr·m²) below the light).

Run from anywhere (optional argument: another output path):
    /usr/bin/python3 content/point_over_plane/make_point_over_plane.py
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from gltf_writer import GltfWriter  # noqa: E402

HALF_SIZE = 2.0          # m
ALBEDO = 0.5
LIGHT_HEIGHT = 1.0       # m
LIGHT_CANDELA = 683.0    # cd → 1 W/sr
CAMERA_HEIGHT = 3.0      # m
CAMERA_YFOV = math.radians(60.0)


def main():
    out_dir = os.path.dirname(os.path.abspath(__file__))
    gltf = GltfWriter("bounce content/point_over_plane/make_point_over_plane.py")
    plane = gltf.material("plane", (ALBEDO, ALBEDO, ALBEDO))
    s = HALF_SIZE
    # Counter-clockwise seen from +y, so the plane faces up.
    a, b, c, d = [-s, 0.0, -s], [-s, 0.0, s], [s, 0.0, s], [s, 0.0, -s]
    gltf.node({"name": "plane", "mesh": gltf.mesh("plane", [[a, b, c], [a, c, d]], plane)})
    gltf.use("KHR_lights_punctual")
    gltf.doc["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"name": "point", "type": "point", "color": [1.0, 1.0, 1.0], "intensity": LIGHT_CANDELA}]}}
    gltf.node({"name": "point_light", "translation": [0.0, LIGHT_HEIGHT, 0.0],
               "extensions": {"KHR_lights_punctual": {"light": 0}}})
    gltf.doc["cameras"] = [{"name": "top", "type": "perspective", "perspective": {
        "yfov": CAMERA_YFOV, "aspectRatio": 1.0, "znear": 0.01, "zfar": 100.0}}]
    # A quarter turn about −x turns the camera's −Z (view) to world −y and its +Y (up) to −z.
    h = math.sqrt(0.5)
    gltf.node({"name": "camera", "camera": 0, "rotation": [-h, 0.0, 0.0, h],
               "translation": [0.0, CAMERA_HEIGHT, 0.0]})
    gltf.write(sys.argv[1] if len(sys.argv) > 1 else os.path.join(out_dir, "point_over_plane.gltf"))


if __name__ == "__main__":
    main()
