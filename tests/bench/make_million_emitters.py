"""The Cornell box plus one emissive mesh of N triangles (default 10^6) with
KHR_materials_emissive_strength: a finely tessellated panel under the ceiling (a grid of
quads, one connected planar piece) or, with --scatter, N separate small triangles over the
ceiling. The area-light stage's worst cases (docs/renderer.md, "Area lights"); run by hand:

  /usr/bin/python3 tests/bench/make_million_emitters.py OUT.gltf [--triangles N] [--scatter]
"""
import argparse
import os
import random
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "content"))
sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "content", "cornell_box"))
from make_cornell_box import build  # noqa: E402


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("out")
    parser.add_argument("--triangles", type=int, default=1000000)
    parser.add_argument("--scatter", action="store_true")
    args = parser.parse_args()
    gltf = build("bounce tests/bench/make_million_emitters.py")
    # 1 W/(sr·m²) white: factor 1, strength 683 nits (the loader divides by 683 lm/W).
    panel = gltf.material("emitter panel", [0.8, 0.8, 0.8], emissive_factor=[1.0, 1.0, 1.0],
                          emissive_strength=683.0)
    y = 0.54
    tris = []
    if args.scatter:
        rng = random.Random(1)
        s = 0.002
        for _ in range(args.triangles):
            x, z = 0.05 + 0.45 * rng.random(), 0.05 + 0.45 * rng.random()
            tris.append([[x, y, z], [x + s, y, z], [x, y, z + s]])  # faces down
    else:
        cols = 1000
        rows = max(1, args.triangles // (2 * cols))
        x0, z0, w, d = 0.1, 0.1, 0.36, 0.36
        for r in range(rows):
            for c in range(cols):
                xa, xb = x0 + w * c / cols, x0 + w * (c + 1) / cols
                za, zb = z0 + d * r / rows, z0 + d * (r + 1) / rows
                tris.append([[xa, y, za], [xb, y, zb], [xa, y, zb]])  # faces down
                tris.append([[xa, y, za], [xb, y, za], [xb, y, zb]])
    gltf.node({"name": "emitter panel", "mesh": gltf.mesh("emitter panel", tris, panel)})
    gltf.write(args.out)


if __name__ == "__main__":
    main()
