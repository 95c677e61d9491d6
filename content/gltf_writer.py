"""A tiny glTF 2.0 writer (standard library only) shared by the content scripts.

Each primitive is a list of triangles with its own vertices and flat normals; all data goes to
one buffer embedded as a base64 data URI, so a scene is a single reproducible .gltf file.
"""
import base64
import json
import math
import struct
import zlib


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return sum(a[i] * b[i] for i in range(3))


def normalize(v):
    n = math.sqrt(dot(v, v))
    return [x / n for x in v]


def triangle_normal(tri):
    return normalize(cross(sub(tri[1], tri[0]), sub(tri[2], tri[0])))


class GltfWriter:
    def __init__(self, generator):
        self.doc = {
            "asset": {"version": "2.0", "generator": generator},
            "scene": 0,
            "scenes": [{"nodes": []}],
            "nodes": [],
            "meshes": [],
            "materials": [],
            "accessors": [],
            "bufferViews": [],
            "buffers": [],
        }
        self.blob = bytearray()

    def _view(self, data, target):
        while len(self.blob) % 4:
            self.blob.append(0)
        self.doc["bufferViews"].append(
            {"buffer": 0, "byteOffset": len(self.blob), "byteLength": len(data), "target": target})
        self.blob.extend(data)
        return len(self.doc["bufferViews"]) - 1

    def _accessor(self, values, kind, with_bounds):
        flat = [x for v in values for x in v]
        dims = len(values[0])
        view = self._view(struct.pack("<%df" % len(flat), *flat), 34962)
        acc = {"bufferView": view, "componentType": 5126, "count": len(values), "type": kind}
        if with_bounds:
            acc["min"] = [min(v[i] for v in values) for i in range(dims)]
            acc["max"] = [max(v[i] for v in values) for i in range(dims)]
        self.doc["accessors"].append(acc)
        return len(self.doc["accessors"]) - 1

    def png_texture(self, name, width, height, srgb_rows):
        """An 8-bit RGB PNG (rows top first, each a list of (r, g, b) bytes) embedded as a data
        URI image with its texture; returns the texture index."""
        raw = b"".join(b"\x00" + bytes(c for px in row for c in px) for row in srgb_rows)

        def chunk(kind, data):
            return (struct.pack(">I", len(data)) + kind + data +
                    struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff))
        png = (b"\x89PNG\r\n\x1a\n" +
               chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
               chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))
        self.doc.setdefault("images", []).append(
            {"name": name, "uri": "data:image/png;base64," + base64.b64encode(png).decode()})
        self.doc.setdefault("samplers", [{"magFilter": 9729, "minFilter": 9987}])
        self.doc.setdefault("textures", []).append(
            {"source": len(self.doc["images"]) - 1, "sampler": 0})
        return len(self.doc["textures"]) - 1

    def material(self, name, base_color, emissive_factor=None, emissive_strength=None,
                 double_sided=False, base_color_texture=None):
        m = {"name": name,
             "pbrMetallicRoughness": {"baseColorFactor": list(base_color) + [1.0],
                                      "metallicFactor": 0.0, "roughnessFactor": 1.0}}
        if base_color_texture is not None:
            m["pbrMetallicRoughness"]["baseColorTexture"] = {"index": base_color_texture}
        if emissive_factor is not None:
            m["emissiveFactor"] = list(emissive_factor)
        if emissive_strength is not None:
            m["extensions"] = {"KHR_materials_emissive_strength":
                               {"emissiveStrength": emissive_strength}}
            self.use("KHR_materials_emissive_strength")
        if double_sided:
            m["doubleSided"] = True
        self.doc["materials"].append(m)
        return len(self.doc["materials"]) - 1

    def mesh(self, name, triangles, material, corner_normals=None, corner_uvs=None):
        """triangles: list of 3 points each, counter-clockwise seen from the front.
        corner_normals: optional unit shading normals, 3 per triangle (smooth surfaces);
        without them each corner gets its triangle's flat normal. corner_uvs: optional
        TEXCOORD_0, 3 per triangle."""
        positions, normals = [], []
        for i, tri in enumerate(triangles):
            n = triangle_normal(tri)
            for k, p in enumerate(tri):
                positions.append(p)
                normals.append(corner_normals[i][k] if corner_normals else n)
        pos = self._accessor(positions, "VEC3", True)
        nor = self._accessor(normals, "VEC3", False)
        attributes = {"POSITION": pos, "NORMAL": nor}
        if corner_uvs:
            attributes["TEXCOORD_0"] = self._accessor(
                [uv for tri in corner_uvs for uv in tri], "VEC2", False)
        self.doc["meshes"].append({"name": name, "primitives": [
            {"attributes": attributes, "material": material, "mode": 4}]})
        return len(self.doc["meshes"]) - 1

    def node(self, node):
        self.doc["nodes"].append(node)
        self.doc["scenes"][0]["nodes"].append(len(self.doc["nodes"]) - 1)
        return len(self.doc["nodes"]) - 1

    def use(self, extension):
        used = self.doc.setdefault("extensionsUsed", [])
        if extension not in used:
            used.append(extension)

    def write(self, path):
        uri = "data:application/octet-stream;base64," + base64.b64encode(bytes(self.blob)).decode()
        self.doc["buffers"] = [{"byteLength": len(self.blob), "uri": uri}]
        with open(path, "w", encoding="utf-8") as f:
            json.dump(self.doc, f, indent=1)
            f.write("\n")
