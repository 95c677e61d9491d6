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


def quad(a, b, c, d):
    """The two triangles of the quad a b c d (counter-clockwise seen from the front)."""
    return [[a, b, c], [a, c, d]]


def subdivided_quad(a, b, c, d, n):
    """Triangles of the quad a b c d (a parallelogram), cut into n x n (n = 1: the two)."""
    if n == 1:
        return [[a, b, c], [a, c, d]]

    def at(i, j):
        return [a[k] + (b[k] - a[k]) * i / n + (d[k] - a[k]) * j / n for k in range(3)]
    triangles = []
    for i in range(n):
        for j in range(n):
            p, q, r, s = at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)
            triangles += [[p, q, r], [p, r, s]]
    return triangles


def take_subdivide(args):
    """Removes `--subdivide N` from the argument list `args`; returns N (1 without it)."""
    if "--subdivide" not in args:
        return 1
    k = args.index("--subdivide")
    n = int(args[k + 1])
    del args[k:k + 2]
    return n


def facing(triangles, outward):
    """The triangles wound so their normals point along `outward`."""
    return [t if dot(triangle_normal(t), outward) > 0 else [t[0], t[2], t[1]] for t in triangles]


def box(lo, hi, face=quad):
    """A closed box, every face wound outwards; face(a, b, c, d) gives each face's triangles."""
    x0, y0, z0 = lo
    x1, y1, z1 = hi
    faces = [
        (face([x0, y0, z0], [x0, y1, z0], [x0, y1, z1], [x0, y0, z1]), [-1, 0, 0]),
        (face([x1, y0, z0], [x1, y1, z0], [x1, y1, z1], [x1, y0, z1]), [1, 0, 0]),
        (face([x0, y0, z0], [x1, y0, z0], [x1, y0, z1], [x0, y0, z1]), [0, -1, 0]),
        (face([x0, y1, z0], [x1, y1, z0], [x1, y1, z1], [x0, y1, z1]), [0, 1, 0]),
        (face([x0, y0, z0], [x1, y0, z0], [x1, y1, z0], [x0, y1, z0]), [0, 0, -1]),
        (face([x0, y0, z1], [x1, y0, z1], [x1, y1, z1], [x0, y1, z1]), [0, 0, 1]),
    ]
    return [t for tris, n in faces for t in facing(tris, n)]


def rotation_looking_along(forward):
    """The unit quaternion (x, y, z, w) that turns a node's -Z to `forward` with +Y kept up."""
    back = normalize([-c for c in forward])
    right = normalize(cross([0.0, 1.0, 0.0], back))
    up = cross(back, right)
    # Columns right, up, back: the node's x, y, z axes in the world.
    m = [[right[0], up[0], back[0]], [right[1], up[1], back[1]], [right[2], up[2], back[2]]]
    trace = m[0][0] + m[1][1] + m[2][2]
    if trace > 0:
        s = 2.0 * math.sqrt(trace + 1.0)
        return [(m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s, s / 4]
    i = max(range(3), key=lambda k: m[k][k])
    j, k = (i + 1) % 3, (i + 2) % 3
    s = 2.0 * math.sqrt(1.0 + m[i][i] - m[j][j] - m[k][k])
    q = [0.0, 0.0, 0.0, (m[k][j] - m[j][k]) / s]
    q[i] = s / 4
    q[j] = (m[j][i] + m[i][j]) / s
    q[k] = (m[k][i] + m[i][k]) / s
    return q


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

    def cameras(self, views, yfov_degrees, aspect, zfar):
        """Perspective cameras, one node each: views = [(name, eye, target), ...] in metres."""
        self.doc["cameras"] = [
            {"name": name, "type": "perspective", "perspective": {
                "yfov": math.radians(yfov_degrees), "aspectRatio": aspect, "znear": 0.01,
                "zfar": zfar}}
            for name, _, _ in views]
        for index, (name, eye, target) in enumerate(views):
            self.node({"name": name, "camera": index,
                       "rotation": rotation_looking_along(normalize(sub(target, eye))),
                       "translation": eye})

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
