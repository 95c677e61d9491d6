#!/usr/bin/python3
"""Writes bounce's corpus of malformed (and a few valid) input files, and manifest.tsv.

Usage: /usr/bin/python3 tests/corpus/make_corpus.py   (stdlib only; deterministic output)

Each manifest row: <path relative to tests/corpus> TAB <expect> TAB <detail>
  error  <substring the LoadError / reader error must contain; the file's name must appear too>
  ok     <properties of the loaded result: key=value;...  (triangles, lights, cameras,
          textures, width, height, nonfinite; bake folders: vpls, vislights = visibility.bin's L)>
The corpus test (tests/corpus/corpus_test.cpp) loads every file through the real loaders;
the fuzz targets (tests/fuzz) start from the same files.
"""
import base64
import json
import os
import random
import struct
import zlib

ROOT = os.path.dirname(os.path.abspath(__file__))
rows = []


def random_bytes(seed, n):
    rng = random.Random(seed)
    return bytes(rng.randrange(256) for _ in range(n))


def random_text(seed, n):
    rng = random.Random(seed)
    return "".join(rng.choice("abcdefghij klmnop\n") for _ in range(n))


def write(rel, data, expect, detail):
    path = os.path.join(ROOT, rel)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())
    if expect is not None:
        rows.append((rel, expect, detail))


# ---------------------------------------------------------------- glTF -----------------------
def triangle_bin(positions=None, indices=(0, 1, 2)):
    positions = positions or [0, 0, 0, 1, 0, 0, 0, 1, 0]
    b = struct.pack("<9f", *positions)
    b += struct.pack("<3H", *indices) + b"\0\0"
    return b


def triangle_doc():
    return {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "tri", "mesh": 0}],
        "meshes": [{"name": "tri", "primitives": [{"attributes": {"POSITION": 0},
                                                   "indices": 1, "mode": 4}]}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
             "min": [0, 0, 0], "max": [1, 1, 0]},
            {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                        {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
        "buffers": [{"byteLength": 44}],
    }


def gltf_bytes(doc, binary):
    d = json.loads(json.dumps(doc))
    if "uri" not in d["buffers"][0]:
        d["buffers"][0]["uri"] = ("data:application/octet-stream;base64," +
                                  base64.b64encode(binary).decode())
    return json.dumps(d, indent=1)


def glb_bytes(doc, binary, json_text=None):
    d = json.loads(json.dumps(doc))
    d["buffers"][0].pop("uri", None)
    j = (json_text if json_text is not None else json.dumps(d)).encode()
    j += b" " * ((4 - len(j) % 4) % 4)
    b = binary + b"\0" * ((4 - len(binary) % 4) % 4)
    out = struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(j) + 8 + len(b))
    out += struct.pack("<I4s", len(j), b"JSON") + j
    out += struct.pack("<I4s", len(b), b"BIN\0") + b
    return out


def gltf_case(name, mutate, expect, detail, binary=None, glb=False):
    doc = triangle_doc()
    b = binary if binary is not None else triangle_bin()
    mutate(doc)
    write("gltf/%s.gltf" % name, gltf_bytes(doc, b), expect, detail)
    if glb:
        write("gltf/%s.glb" % name, glb_bytes(doc, b), expect, detail)


def setp(path, value):
    """A mutation setting doc[path...] = value (path: list of keys/indices)."""
    def mutate(d):
        for k in path[:-1]:
            d = d[k]
        d[path[-1]] = value
    return mutate


def delp(path):
    def mutate(d):
        for k in path[:-1]:
            d = d[k]
        del d[path[-1]]
    return mutate


def both(*mutations):
    def mutate(d):
        for m in mutations:
            m(d)
    return mutate


def with_light(light, node_extra=None):
    def mutate(d):
        d["extensions"] = {"KHR_lights_punctual": {"lights": [light]}}
        d["extensionsUsed"] = ["KHR_lights_punctual"]
        d["nodes"][0]["extensions"] = {"KHR_lights_punctual": {"light": 0}}
        if node_extra:
            d["nodes"][0].update(node_extra)
    return mutate


def with_emission(strength):
    def mutate(d):
        d["materials"] = [{"emissiveFactor": [1, 1, 1], "extensions": {
            "KHR_materials_emissive_strength": {"emissiveStrength": strength}}}]
        d["meshes"][0]["primitives"][0]["material"] = 0
    return mutate


def with_camera(perspective, kind="perspective"):
    def mutate(d):
        d["cameras"] = [{"type": kind, "perspective": perspective}]
        d["nodes"][0]["camera"] = 0
    return mutate


nothing = setp(["asset", "generator"], "bounce corpus")
gltf_case("ok_triangle", nothing, "ok", "triangles=1", glb=True)
gltf_case("ok_point_light", with_light({"type": "point", "intensity": 683.0}),
          "ok", "triangles=1;lights=1")
gltf_case("ok_camera", with_camera({"yfov": 0.7, "znear": 0.01}), "ok", "cameras=1")
gltf_case("ok_at_coordinate_limit", setp(["nodes", 0, "translation"], [0, 0, 999000.0]),
          "ok", "triangles=1")
gltf_case("ok_at_radiometric_limit", with_light({"type": "point", "intensity": 6.83e14}),
          "ok", "lights=1")
gltf_case("ok_unknown_optional_extension", setp(["extensionsUsed"], ["EXT_whatever"]),
          "ok", "triangles=1")

# JSON types and values (each was once taken silently).
types = [
    ("neg_byteoffset", setp(["accessors", 0, "byteOffset"], -4), "accessors[0].byteOffset must be in 0.."),
    ("emissive_strength_string", with_emission("abc"), "emissiveStrength must be a number"),
    ("translation_strings", setp(["nodes", 0, "translation"], ["1", "2", "3"]), "translation must be an array of 3 finite numbers"),
    ("translation_two", setp(["nodes", 0, "translation"], [1, 2]), "translation must be an array of 3"),
    ("mesh_fraction", setp(["nodes", 0, "mesh"], 0.5), "nodes[0].mesh must be an integer"),
    ("primitives_null", setp(["meshes", 0, "primitives"], None), "primitives must be a non-empty array"),
    ("primitives_empty", setp(["meshes", 0, "primitives"], []), "primitives must be a non-empty array"),
    ("ext_required_string", setp(["extensionsRequired"], "KHR_draco_mesh_compression"), "extensionsRequired must be an array of strings"),
    ("version_3", setp(["asset", "version"], "3.0"), "bounce reads glTF 2.x"),
    ("version_number", setp(["asset", "version"], 2.0), "asset.version must be a string"),
    ("min_version_2_1", setp(["asset", "minVersion"], "2.1"), "asset.minVersion"),
    ("no_asset", delp(["asset"]), "asset is required"),
    ("scene_negative", setp(["scene"], -1), "scene must be in 0.."),
    ("nodes_object", setp(["nodes"], {"a": 1}), "nodes must be an array"),
    ("node_not_object", setp(["nodes", 0], 7), "nodes[0] must be a JSON object"),
    ("children_string", setp(["nodes", 0, "children"], "1"), "children must be an array of indices"),
    ("children_negative", setp(["nodes", 0, "children"], [-2]), "non-negative integer indices"),
    ("matrix_15", setp(["nodes", 0, "matrix"], [1] * 15), "matrix must be an array of 16"),
    ("rotation_strings", setp(["nodes", 0, "rotation"], ["0", "0", "0", "1"]), "rotation must be an array of 4"),
    ("scale_overflow", setp(["nodes", 0, "scale"], [1, 1, "x"]), "scale must be an array of 3"),
    ("count_zero", setp(["accessors", 0, "count"], 0), "count must be in 1.."),
    ("count_string", setp(["accessors", 0, "count"], "3"), "count must be an integer"),
    ("component_type_bad", setp(["accessors", 0, "componentType"], 5127), "componentType must be in 5120..5126"),
    ("type_missing", delp(["accessors", 0, "type"]), "accessors[0].type is required"),
    ("normalized_string", setp(["accessors", 0, "normalized"], "false"), "normalized must be true or false"),
    ("view_length_zero", setp(["bufferViews", 0, "byteLength"], 0), "byteLength must be in 1.."),
    ("view_stride_2", setp(["bufferViews", 0, "byteStride"], 2), "byteStride must be in 4..252"),
    ("view_buffer_missing", delp(["bufferViews", 0, "buffer"]), "bufferViews[0].buffer is required"),
    ("buffer_length_missing", delp(["buffers", 0, "byteLength"]), "buffers[0].byteLength is required"),
    ("uri_number", setp(["buffers", 0, "uri"], 5), "buffers[0].uri must be a string"),
    ("attributes_missing", delp(["meshes", 0, "primitives", 0, "attributes"]), "attributes is required"),
    ("position_negative", setp(["meshes", 0, "primitives", 0, "attributes", "POSITION"], -1), "attributes.POSITION must be in 0.."),
    ("indices_fraction", setp(["meshes", 0, "primitives", 0, "indices"], 1.5), "indices must be an integer"),
    ("mode_7", setp(["meshes", 0, "primitives", 0, "mode"], 7), "mode must be in 0..6"),
    ("base_color_5", setp(["materials"], [{"pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1, 1]}}]), "baseColorFactor must be an array of 4"),
    ("base_color_2", setp(["materials"], [{"pbrMetallicRoughness": {"baseColorFactor": [2, 1, 1, 1]}}]), "baseColorFactor must be an array of 4 finite numbers in [0"),
    ("emissive_negative", setp(["materials"], [{"emissiveFactor": [-1, 0, 0]}]), "emissiveFactor must be an array of 3"),
    ("double_sided_string", setp(["materials"], [{"doubleSided": "yes"}]), "doubleSided must be true or false"),
    ("texture_info_string", setp(["materials"], [{"pbrMetallicRoughness": {"baseColorTexture": 0}}]), "baseColorTexture must be a JSON object"),
    ("camera_yfov_string", with_camera({"yfov": "wide", "znear": 0.1}), "yfov must be a number"),
    ("camera_znear_missing", with_camera({"yfov": 0.7}), "znear is required"),
    ("light_color_two", with_light({"type": "point", "color": [1, 1]}), "color must be an array of 3"),
    ("light_intensity_negative", with_light({"type": "point", "intensity": -1}), "intensity must be a finite number in [0"),
    ("light_type_missing", with_light({"intensity": 1}), "type is required"),
    ("light_index_string", with_light({"type": "point"}, {"extensions": {"KHR_lights_punctual": {"light": "0"}}}), "light must be an integer"),
    ("number_overflow", setp(["nodes", 0, "translation"], [0, 0, "1e400"]), "translation must be an array of 3"),
]
for name, mutate, reason in types:
    gltf_case("type_" + name, mutate, "error", reason, glb=name in (
        "neg_byteoffset", "mesh_fraction", "primitives_null", "version_3", "ext_required_string"))

# Values the loader checks after tinygltf: indices, ranges, limits.
values = [
    ("material_oob", setp(["meshes", 0, "primitives", 0, "material"], 5), "material index 5 is out of range"),
    ("mesh_oob", setp(["nodes", 0, "mesh"], 3), "mesh index 3 is out of range"),
    ("camera_oob", setp(["nodes", 0, "camera"], 2), "camera index 2 is out of range"),
    ("cycle", both(setp(["nodes", 0, "children"], [1]), setp(["nodes"], [{"mesh": 0, "children": [1]}, {"children": [0]}])), "is reached twice"),
    ("view_oob", setp(["accessors", 0, "bufferView"], 9), "bufferView 9 is out of range"),
    ("accessor_past_view", setp(["accessors", 0, "count"], 4), "exceeds its bufferView"),
    ("view_past_buffer", setp(["bufferViews", 0, "byteLength"], 400), "exceeds buffer 0"),
    ("required_draco", setp(["extensionsRequired"], ["KHR_draco_mesh_compression"]), "unsupported extension 'KHR_draco_mesh_compression'"),
    ("points_mode", setp(["meshes", 0, "primitives", 0, "mode"], 0), "mode 0"),
    ("camera_ortho", with_camera({"yfov": 0.7, "znear": 0.1}, "orthographic"), "Orthographic camera"),
    ("camera_znear_tiny", with_camera({"yfov": 0.7, "znear": 1e-50}), "below bounce's limit of 1e-6 m"),
    ("camera_yfov_pi", with_camera({"yfov": 3.2, "znear": 0.1}), "0 < yfov < pi"),
    ("spot_cones_swapped", with_light({"type": "spot", "spot": {"innerConeAngle": 0.5, "outerConeAngle": 0.2}}), "spot cone angles"),
    ("light_type_area", with_light({"type": "area"}), "unknown light type 'area'"),
    ("point_1e40_cd", with_light({"type": "point", "intensity": 1e40}), "exceeds bounce's limit of 1e12"),
    ("point_1e39_cd", with_light({"type": "point", "intensity": 1e39}), "exceeds bounce's limit of 1e12"),
    ("sun_1e39_lux", with_light({"type": "directional", "intensity": 1e39}), "light irradiance W/m²"),
    ("emission_2e41", with_emission(2e41), "emitted radiance W/(sr·m²)"),
    ("emission_negative", with_emission(-1), "emissiveStrength must be a finite number in [0"),
    ("root_scale_1e19", setp(["nodes", 0, "scale"], [1e19, 1e19, 1e19]), "beyond bounce's coordinate limit"),
    ("translation_5e9", setp(["nodes", 0, "translation"], [0, 5e9, 0]), "beyond bounce's coordinate limit"),
    ("translation_3e38", setp(["nodes", 0, "translation"], [3e38, 0, 0]), "beyond bounce's coordinate limit"),
    ("light_far", with_light({"type": "point"}, {"mesh": 0, "translation": [2e6, 0, 0]}), "coordinate limit"),
    ("scale_zero_camera", both(with_camera({"yfov": 0.7, "znear": 0.1}), setp(["nodes", 0, "scale"], [0, 0, 0])), "degenerate transform"),
    ("mobility_bad", setp(["nodes", 0, "extras"], {"bounce": {"mobility": "sometimes"}}), "mobility must be"),
    ("sparse", setp(["accessors", 0, "sparse"], {"count": 1, "indices": {"bufferView": 1, "componentType": 5123}, "values": {"bufferView": 0}}), "sparse"),
    ("texcoord_1", both(setp(["images"], [{"uri": "../png/ok_2x2.png"}]), setp(["textures"], [{"source": 0}]), setp(["materials"], [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0, "texCoord": 1}}}]), setp(["meshes", 0, "primitives", 0, "material"], 0)), "TEXCOORD_1"),
    ("texture_oob", both(setp(["materials"], [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 4}}}]), setp(["meshes", 0, "primitives", 0, "material"], 0)), "texture index 4 is out of range"),
]
for name, mutate, reason in values:
    gltf_case("value_" + name, mutate, "error", reason)

for name, x, reason in [("coord_1e20", 1e20, "coordinate limit"), ("coord_3e38", 3e38, "coordinate limit"),
                        ("coord_neg_3e38", -3e38, "coordinate limit"), ("coord_nan", float("nan"), "not finite"),
                        ("coord_inf", float("inf"), "not finite")]:
    gltf_case("buffer_" + name, nothing, "error", reason,
              binary=triangle_bin([0, 0, 0, x, 0, 0, 0, 1, 0]), glb=name == "coord_nan")
gltf_case("buffer_index_oob", nothing, "error", "index 7 (element 1) is out of range",
          binary=triangle_bin(indices=(0, 7, 2)))

# Nesting depth: the limit is 64 levels of arrays/objects in all.
def nested(levels):
    doc = triangle_doc()
    doc["extras"] = "NEST"
    text = gltf_bytes(doc, triangle_bin())
    return text.replace('"NEST"', "[" * levels + "]" * levels)


write("gltf/depth_100000.gltf", nested(100000), "error", "deeper than 64 levels")
write("gltf/depth_64_levels.gltf", nested(64), "error", "deeper than 64 levels")
write("gltf/ok_depth_63_in_extras.gltf", nested(63), "ok", "triangles=1")
write("gltf/depth_objects.gltf", nested(0).replace('"asset"', '"x":' + '{"a":' * 5000 + "1" + "}" * 5000 + ',"asset"'),
      "error", "deeper than 64 levels")

# Not JSON / not glTF.
write("gltf/empty.gltf", b"", "error", "invalid glTF")
write("gltf/truncated_json.gltf", gltf_bytes(triangle_doc(), triangle_bin())[:120], "error", "invalid glTF")
write("gltf/json_array_root.gltf", "[1, 2, 3]", "error", "must be a JSON object")
write("gltf/binary_junk.gltf", random_bytes(1, 4096), "error", "invalid glTF")
doc = triangle_doc(); doc["asset"]["copyright"] = "[{" * 200 + '\\"'  # brackets inside a string
write("gltf/ok_brackets_in_string.gltf", gltf_bytes(doc, triangle_bin()), "ok", "triangles=1")

# Referenced files.
doc = triangle_doc(); doc["buffers"][0]["uri"] = "absent.bin"
write("gltf/uri_missing.gltf", gltf_bytes(doc, triangle_bin()), "error", "absent.bin")
doc = triangle_doc(); doc["buffers"][0]["uri"] = "."
write("gltf/uri_is_folder.gltf", gltf_bytes(doc, triangle_bin()), "error", "is a directory")
doc = triangle_doc(); doc["buffers"][0]["uri"] = "data:application/octet-stream;base64,@@@@"
write("gltf/uri_bad_base64.gltf", gltf_bytes(doc, triangle_bin()), "error", "invalid glTF")
doc = triangle_doc(); doc["buffers"][0]["byteLength"] = 4400
write("gltf/buffer_shorter_than_declared.gltf", gltf_bytes(doc, triangle_bin()), "error", "invalid glTF")


def textured(image_uri):
    def mutate(d):
        d["images"] = [{"uri": image_uri}]
        d["textures"] = [{"source": 0}]
        d["materials"] = [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}]
        d["meshes"][0]["primitives"][0]["material"] = 0
    return mutate


gltf_case("ok_texture_2x2", textured("../png/ok_2x2.png"), "ok", "textures=1")
gltf_case("texture_17000x1", textured("../png/wide_17000x1.png"), "error", "17000x1 texels exceeds bounce's texture limit")
gltf_case("texture_1x17000", textured("../png/tall_1x17000.png"), "error", "1x17000 texels exceeds")
gltf_case("ok_texture_16384x1", textured("../png/ok_16384x1.png"), "ok", "textures=1")
gltf_case("texture_truncated", textured("../png/truncated.png"), "error", "invalid glTF")
gltf_case("texture_missing", textured("../png/absent.png"), "error", "absent.png")
gltf_case("texture_not_png", textured("../png/not_an_image.png"), "error", "invalid glTF")

# GLB containers.
base = glb_bytes(triangle_doc(), triangle_bin())
write("glb/truncated_header.glb", base[:10], "error", "truncated GLB")
write("glb/bad_magic.glb", b"gLTF" + base[4:], "error", "not a GLB file")
write("glb/version_1.glb", base[:4] + struct.pack("<I", 1) + base[8:], "error", "GLB version 1")
write("glb/length_mismatch.glb", base[:8] + struct.pack("<I", len(base) + 4) + base[12:], "error", "header declares")
write("glb/cut_in_json.glb", base[:40], "error", "truncated")
write("glb/cut_in_bin.glb", base[:-8], "error", "truncated")
write("glb/json_chunk_too_long.glb", base[:12] + struct.pack("<I", 10 ** 6) + base[16:], "error", "JSON chunk exceeds the file")
write("glb/first_chunk_bin.glb", base[:16] + b"BIN\0" + base[20:], "error", "first chunk is not JSON")
write("glb/json_is_garbage.glb", glb_bytes(triangle_doc(), triangle_bin(), json_text="{{{{"), "error", "not valid JSON")
write("glb/depth_100000.glb", glb_bytes(triangle_doc(), triangle_bin(), json_text="[" * 100000 + "]" * 100000), "error", "deeper than 64 levels")
bin_start = 20 + struct.unpack("<I", base[12:16])[0]  # 4 bytes of the BIN chunk header kept
write("glb/bin_chunk_header_cut.glb", base[:8] + struct.pack("<I", bin_start + 4) + base[12:bin_start + 4],
      "error", "incomplete BIN chunk header")

# ---------------------------------------------------------------- PNG (textures) -------------
def png(width, height, rgb=(128, 128, 128)):
    raw = b"".join(b"\0" + bytes(rgb) * width for _ in range(height))
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


write("png/ok_2x2.png", png(2, 2), None, None)
write("png/wide_17000x1.png", png(17000, 1), None, None)
write("png/tall_1x17000.png", png(1, 17000), None, None)
write("png/ok_16384x1.png", png(16384, 1), None, None)
write("png/truncated.png", png(4, 4)[:30], None, None)
write("png/not_an_image.png", "this is text", None, None)

# ---------------------------------------------------------------- OBJ / MTL ------------------
TRI = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"
write("obj/ok_triangle.obj", TRI, "ok", "triangles=1")
write("obj/ok_quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n", "ok", "triangles=2")
write("obj/ok_crlf_comments.obj", "# box\r\n" + TRI.replace("\n", "\r\n") + "# end\r\n", "ok", "triangles=1")
write("obj/ok_negative_indices.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n", "ok", "triangles=1")
write("obj/ok_at_coordinate_limit.obj", "v 0 0 0\nv 999999 0 0\nv 0 1 0\nf 1 2 3\n", "ok", "triangles=1")
write("obj/ok_materials.obj", "mtllib ok.mtl\n" + "usemtl red\n".join(["", TRI]), "ok", "triangles=1")
write("obj/ok.mtl", "newmtl red\nKd 0.8 0.1 0.1  # red\nKe 0 0 0\nNs 10\n", None, None)
write("obj/ok_textured.obj", "mtllib tex.mtl\nusemtl t\nvt 0 0\nvt 1 0\nvt 0 1\n" +
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1 2/2 3/3\n", "ok", "textures=1")
write("obj/tex.mtl", "newmtl t\nKd 1 1 1\nmap_Kd ../png/ok_2x2.png\n", None, None)
for name, line, reason in [
        ("v_nan", "v nan 0 0", "'nan' in 'v' is not a finite number"),
        ("v_inf", "v inf 0 0", "'inf' in 'v'"), ("v_neg_inf", "v -inf 0 0", "'-inf' in 'v'"),
        ("v_1e999", "v 1e999 0 0", "'1e999' in 'v'"), ("v_two", "v 1 2", "'v' takes 3-4 numbers"),
        ("v_five", "v 1 2 3 4 5", "'v' takes 3-4 numbers"), ("v_word", "v a b c", "'a' in 'v'"),
        ("v_2e6", "v 2e6 0 0", "'2e6' in 'v' is not a finite number within ±1e6 m"), ("v_hex", "v 0x10 0 0", "'0x10' in 'v'"),
        ("vn_nan", "vn nan 0 1", "'nan' in 'vn'"), ("vt_inf", "vt inf 0", "'inf' in 'vt'"),
        ("v_1e20", "v 1e20 0 0", "'1e20' in 'v' is not a finite number within ±1e6 m"),
        ("v_3e38", "v 3e38 0 0", "'3e38' in 'v'")]:
    write("obj/%s.obj" % name, line + "\n" + TRI, "error", "line 1: " + reason)
for name, line, reason in [
        ("kd_nan", "Kd nan 0.5 0.5", "'nan' in 'Kd'"), ("ke_inf", "Ke inf 1 1", "'inf' in 'Ke'"),
        ("kd_word", "Kd red", "'red' in 'Kd'"), ("kd_four", "Kd 1 1 1 1", "'Kd' takes 1-3 numbers"),
        ("ns_nan", "Ns nan", "'nan' in 'Ns'")]:
    write("obj/mtl_%s.mtl" % name, "newmtl m\n" + line + "\n", None, None)
    write("obj/mtl_%s.obj" % name, "mtllib mtl_%s.mtl\nusemtl m\n" % name + TRI, "error", "material library 'mtl_%s.mtl': line 2: %s" % (name, reason))
write("obj/mtl_ke_1e13.mtl", "newmtl m\nKe 1e13 1 1\n", None, None)
write("obj/mtl_ke_1e13.obj", "mtllib mtl_ke_1e13.mtl\nusemtl m\n" + TRI, "error", "radiance limit of 1e12")
write("obj/mtl_kd_negative.mtl", "newmtl m\nKe -1 0 0\n", None, None)
write("obj/mtl_kd_negative.obj", "mtllib mtl_kd_negative.mtl\nusemtl m\n" + TRI, "error", "negative or non-finite Kd or Ke")
write("obj/mtllib_missing.obj", "mtllib absent.mtl\nusemtl m\n" + TRI, "error", "'absent.mtl'")
write("obj/mtllib_is_folder.obj", "mtllib .\nusemtl m\n" + TRI, "error", "is a directory")
write("obj/usemtl_undefined.obj", "mtllib ok.mtl\nusemtl light\n" + TRI, "error", "'light' is used (usemtl) but not defined")
write("obj/map_kd_missing.mtl", "newmtl m\nmap_Kd ../png/absent.png\n", None, None)
write("obj/map_kd_missing.obj", "mtllib map_kd_missing.mtl\nusemtl m\n" + TRI, "error", "absent.png")
write("obj/map_kd_17000x1.mtl", "newmtl m\nmap_Kd ../png/wide_17000x1.png\n", None, None)
write("obj/map_kd_17000x1.obj", "mtllib map_kd_17000x1.mtl\nusemtl m\n" + TRI, "error", "17000x1 texels exceeds")
write("obj/map_kd_text.mtl", "newmtl m\nmap_Kd ../png/not_an_image.png\n", None, None)
write("obj/map_kd_text.obj", "mtllib map_kd_text.mtl\nusemtl m\n" + TRI, "error", "not_an_image.png")
write("obj/face_index_oob.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", "error", "vertex 9 of 3")
write("obj/face_index_zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "error", "invalid OBJ")
write("obj/no_faces.obj", "v 0 0 0\nv 1 0 0\n", "error", "no faces")
write("obj/empty.obj", "", "error", "no faces")
write("obj/comments_only.obj", "# a comment\n# another\n", "error", "no faces")
write("obj/random_64k.obj", random_bytes(9, 65536), "error", "not a text file")
write("obj/nul_byte.obj", "v 0 0 0\0\n" + TRI, "error", "binary data (control byte 0)")
write("obj/text_noise.obj", random_text(3, 4096), "error", "invalid OBJ")

# ---------------------------------------------------------------- EXR ------------------------
def attribute(name, kind, data):
    return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(data)) + data


def exr(width, height, pixel_type=2, channels="BGR", values=None, flags=0, tamper=None, window=None):
    """An uncompressed scanline EXR; pixel_type 0 UINT, 1 HALF, 2 FLOAT; channel order as given
    (EXR stores them sorted)."""
    chlist = b"".join(c.encode() + b"\0" + struct.pack("<iB3xii", pixel_type, 0, 1, 1) for c in channels) + b"\0"
    x0, y0, x1, y1 = window or (0, 0, width - 1, height - 1)
    header = (attribute("channels", "chlist", chlist) +
              attribute("compression", "compression", b"\0") +
              attribute("dataWindow", "box2i", struct.pack("<4i", x0, y0, x1, y1)) +
              attribute("displayWindow", "box2i", struct.pack("<4i", 0, 0, width - 1, height - 1)) +
              attribute("lineOrder", "lineOrder", b"\0") +
              attribute("pixelAspectRatio", "float", struct.pack("<f", 1.0)) +
              attribute("screenWindowCenter", "v2f", struct.pack("<2f", 0, 0)) +
              attribute("screenWindowWidth", "float", struct.pack("<f", 1.0)) + b"\0")
    head = b"\x76\x2f\x31\x01" + struct.pack("<I", 2 | flags) + header
    size = {0: 4, 1: 2, 2: 4}[pixel_type]
    blocks = []
    for y in range(height):
        data = b""
        for c in range(len(channels)):
            for x in range(width):
                v = values(x, y, c) if values else 0.25 * (c + 1)
                data += (struct.pack("<I", int(v)) if pixel_type == 0 else
                         struct.pack("<e", v) if pixel_type == 1 else struct.pack("<f", v))
        blocks.append(struct.pack("<ii", y, len(data)) + data)
    offsets, at = [], len(head) + 8 * height
    for b in blocks:
        offsets.append(at)
        at += len(b)
    out = head + b"".join(struct.pack("<Q", o) for o in offsets) + b"".join(blocks)
    return tamper(out) if tamper else out


write("exr/ok_float_2x2.exr", exr(2, 2), "ok", "width=2;height=2")
write("exr/ok_half_3x1.exr", exr(3, 1, pixel_type=1), "ok", "width=3;height=1")
write("exr/ok_grey_Y.exr", exr(2, 1, channels="Y"), "ok", "width=2")
write("exr/ok_nan_pixel.exr", exr(2, 1, values=lambda x, y, c: float("nan") if x == 0 else 1.0), "ok", "nonfinite=1")
write("exr/uint_channels.exr", exr(2, 2, pixel_type=0, values=lambda x, y, c: 7), "error", "holds UINT values")
write("exr/uint_one_channel.exr", exr(2, 2, pixel_type=0, channels="R"), "error", "holds UINT")
write("exr/no_rgb.exr", exr(2, 2, channels="AZ"), "error", "no R, G and B channels")
write("exr/bad_magic.exr", b"\x00\x00\x00\x00" + exr(2, 2)[4:], "error", "not an OpenEXR file")
write("exr/empty.exr", b"", "error", "not an OpenEXR file")
write("exr/text.exr", "not an exr", "error", "not an OpenEXR file")
write("exr/multipart_flag.exr", exr(2, 2, flags=0x1000), "error", "multi-part")
write("exr/deep_flag.exr", exr(2, 2, flags=0x800), "error", "multi-part and deep")
write("exr/truncated_header.exr", exr(2, 2)[:60], "error", "cannot read EXR")
write("exr/truncated_pixels.exr", exr(4, 4)[:-20], "error", "cannot read EXR")
def offsets_past_end(b):  # the first scanline offset points past the end of the file
    at = b.index(b"screenWindowWidth\0float\0") + len("screenWindowWidth\0float\0") + 4 + 4 + 1
    return b[:at] + struct.pack("<Q", 10 ** 9) + b[at + 8:]


write("exr/offset_past_end.exr", exr(2, 2, tamper=offsets_past_end), "error", "cannot read EXR")
write("exr/huge_window.exr", exr(2, 2, window=(0, 0, 2000000000, 2000000000)), "error", "cannot read EXR")
write("exr/inverted_window.exr", exr(2, 2, window=(5, 5, 0, 0)), "error", "cannot read EXR")
# The tiled bit without tile attributes: tinyexr reads the scanline data, which is right.
write("exr/ok_tiled_flag_only.exr", exr(2, 2, flags=0x200), "ok", "width=2;height=2")


def with_type(value):  # a `type` attribute before the end of the header
    def tamper(b):
        at = b.index(b"screenWindowWidth\0")
        return b[:at] + attribute("type", "string", value) + b[at:]
    return tamper


write("exr/type_unknown.exr", exr(2, 2, tamper=with_type(b"els")), "error", "header attribute type 'els'")
write("exr/type_tiled_on_scanline.exr", exr(2, 2, tamper=with_type(b"tiledimage")), "error", "header attribute type 'tiledimage'")


def with_chunk_count(count):  # tinyexr sized its offset table from chunkCount unchecked
    def tamper(b):
        at = b.index(b"screenWindowWidth\0")
        return b[:at] + attribute("chunkCount", "int", struct.pack("<i", count)) + b[at:]
    return tamper


write("exr/chunk_count_huge.exr", exr(2, 2, tamper=with_chunk_count(1 << 30)), "error", "chunkCount 1073741824 exceeds the 2 scanlines")
write("exr/window_pixels_over_limit.exr", exr(2, 2, window=(0, 0, 3, 1 << 28)), "error", "exceeds bounce's limit of 67108864 pixels")

# ---------------------------------------------------------------- bake folders -------------
# readBake (engine/bake_folder/bake_folder.h) against tests/corpus/bake/scene.gltf: a floor, a wall and a
# 0.4 m x 0.4 m emissive panel facing down through the top of the wall (three static instances;
# the panel is the one static area light, so bounce-bake writes visibility.bin) and a point light. bake/valid.bake is bounce-bake's own output,
# committed; regenerate it (after a format or scene-hash change) with
#   build/release/bin/bounce-bake tests/corpus/bake/scene.gltf -o tests/corpus/bake/valid.bake \
#     --texel-budget 64 --spp 16 --vpls 16 --quiet
# Every other folder is valid.bake with one file tampered. bake.json records every file's size and
# FNV-1a 64 hash ("files"): a tampered file is re-recorded (stamped) there, as a forger would, so
# that the check under test is reached, unless the case is about the hash (stamp=False). Rows:
# "<folder> error <reason>".
def bake_scene():
    # (corners, normal) floor 2 m x 2 m at y = 0; wall at x = -1; panel at y = 1.9 straddling
    # the wall, so the wall hides part of it from the floor and the texels' V lie inside (0, 1)
    quads = [
        ([(-1, 0, -1), (-1, 0, 1), (1, 0, 1), (1, 0, -1)], (0, 1, 0)),
        ([(-1, 0, -1), (-1, 2, -1), (-1, 2, 1), (-1, 0, 1)], (1, 0, 0)),
        ([(-1.2, 1.9, -0.2), (-0.8, 1.9, -0.2), (-0.8, 1.9, 0.2), (-1.2, 1.9, 0.2)], (0, -1, 0)),
    ]
    binary, views, accessors, meshes, nodes = b"", [], [], [], []
    for i, (corners, normal) in enumerate(quads):
        for data, kind, count in ((struct.pack("<12f", *sum(corners, ())), "VEC3", 4),
                                  (struct.pack("<12f", *(normal * 4)), "VEC3", 4),
                                  (struct.pack("<6H", 0, 1, 2, 0, 2, 3) + b"\0\0", "SCALAR", 6)):
            views.append({"buffer": 0, "byteOffset": len(binary), "byteLength": len(data) if kind != "SCALAR" else 12})
            accessor = {"bufferView": len(views) - 1, "componentType": 5126 if kind == "VEC3" else 5123,
                        "count": count, "type": kind}
            if len(accessors) % 3 == 0:
                accessor["min"] = [min(c[k] for c in corners) for k in range(3)]
                accessor["max"] = [max(c[k] for c in corners) for k in range(3)]
            accessors.append(accessor)
            binary += data
        meshes.append({"primitives": [{"attributes": {"POSITION": 3 * i, "NORMAL": 3 * i + 1},
                                       "indices": 3 * i + 2, "material": 1 if i == 2 else 0}]})
        nodes.append({"name": ["floor", "wall", "panel"][i], "mesh": i})
    nodes.append({"name": "lamp", "translation": [0, 1.5, 0], "extensions": {"KHR_lights_punctual": {"light": 0}}})
    doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1, 2, 3]}], "nodes": nodes,
           "meshes": meshes, "accessors": accessors, "bufferViews": views,
           "buffers": [{"byteLength": len(binary)}],
           "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.6, 0.4, 1]}},
                         {"emissiveFactor": [1, 0.9, 0.8],  # radiance 3 x this, W/(sr·m²)
                          "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 3.0}}}],
           "extensionsUsed": ["KHR_lights_punctual", "KHR_materials_emissive_strength"],
           "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "intensity": 5.0}]}}}
    return gltf_bytes(doc, binary)


write("bake/scene.gltf", bake_scene(), "ok", "triangles=6;lights=1")
VALID = os.path.join(ROOT, "bake", "valid.bake")
BAKE_FILES = ("bake.json", "layout.bin", "lightmap.exr", "vpls", "visibility.bin", "error.exr")


def fnv1a64(data):
    h = 14695981039346656037
    for c in data:
        h = ((h ^ c) * 1099511628211) & 0xFFFFFFFFFFFFFFFF
    return "%016x" % h


def bake_file(name):
    with open(os.path.join(VALID, name), "rb") as f:
        return f.read()


def bake_case(name, expect, detail, stamp=True, **files):
    """A copy of valid.bake with files replaced (bytes) or removed (None); with `stamp`, the
    replaced files' sizes and hashes are recorded in its bake.json (unless bake.json is replaced
    too)."""
    folder = "bake/%s.bake" % name
    contents = {f: files.get(f.replace(".", "_"), bake_file(f)) for f in BAKE_FILES}
    if stamp and "bake_json" not in files:
        m = json.loads(bake_file("bake.json"))
        for f, content in contents.items():
            if f != "bake.json" and content is not None and f.replace(".", "_") in files:
                m["files"][f] = {"bytes": len(content), "hash": fnv1a64(content)}
        contents["bake.json"] = json.dumps(m, indent=1, sort_keys=True).encode()
    for f in BAKE_FILES:
        path = os.path.join(ROOT, folder, f)
        content = contents[f]
        if os.path.exists(path):
            os.remove(path)
        if content is not None:
            write(os.path.join(folder, f), content, None, None)
    os.makedirs(os.path.join(ROOT, folder), exist_ok=True)
    rows.append((folder, expect, detail))


if os.path.isdir(VALID):
    manifest = json.loads(bake_file("bake.json"))
    layout, vpls, vis = bake_file("layout.bin"), bake_file("vpls"), bake_file("visibility.bin")
    rows.append(("bake/valid.bake", "ok", "width=%d;height=%d;vpls=%d;vislights=%d" % (
        struct.unpack_from("<ii", layout, 12) + struct.unpack_from("<I", vpls, 12) +
        struct.unpack_from("<I", vis, 20))))

    def manifest_with(**kv):
        m = dict(manifest)
        m.update(kv)
        return json.dumps(m).encode()

    def layout_with(offset, fmt, *values):
        b = bytearray(layout)
        struct.pack_into(fmt, b, offset, *values)
        return bytes(b)

    def vpls_with(offset, fmt, *values):
        b = bytearray(vpls)
        struct.pack_into(fmt, b, offset, *values)
        return bytes(b)

    bake_case("manifest_missing", "error", "bake.json: missing", bake_json=None)
    bake_case("manifest_not_json", "error", "bake.json: not JSON", bake_json=b"{\"formatVersion\": 1,")
    bake_case("manifest_array", "error", "bake.json: not a JSON object", bake_json=b"[1, 2]")
    bake_case("manifest_deep", "error", "bake.json: JSON nests arrays/objects deeper than 64",
              bake_json=b"{\"x\": " + b"[" * 100000 + b"]" * 100000 + b"}")
    bake_case("manifest_version_string", "error", "no integer \"formatVersion\"", bake_json=manifest_with(formatVersion="1"))
    bake_case("manifest_version_1", "error", "format version 1, this build reads version 2: rebake", bake_json=manifest_with(formatVersion=1))
    # A 64-bit version that a 32-bit read would take as 1 or as this build's 2.
    for v in (2 ** 32 + 1, 2 ** 32 + 2):
        bake_case("manifest_version_%d" % v, "error", "format version %d, this build reads version 2: rebake" % v,
                  bake_json=manifest_with(formatVersion=v))
    bake_case("manifest_version_2_0", "error", "no integer \"formatVersion\"", bake_json=manifest_with(formatVersion=2.0))
    bake_case("manifest_no_files", "error", "bake.json: no \"files\" (the sizes and hashes of the folder's files): rebake",
              bake_json=json.dumps({k: v for k, v in manifest.items() if k != "files"}).encode())
    bake_case("manifest_atlas_width_2_32", "error", "\"atlas.width\" is 4294967312, out of range 1..65536",
              bake_json=manifest_with(atlas=dict(manifest["atlas"], width=2 ** 32 + 16)))
    bake_case("manifest_atlas_other_size", "error", "layout.bin: is %dx%d, bake.json's atlas is 64x8: another bake's" % struct.unpack_from("<ii", layout, 12),
              bake_json=manifest_with(atlas=dict(manifest["atlas"], width=64)))
    bake_case("manifest_clamp_overflows", "error", "\"vpls.clampDistance\" is 1e+39, out of range [0, 1e+06]",
              bake_json=manifest_with(vpls=dict(manifest["vpls"], clampDistance=1e39)))
    bake_case("manifest_vpl_count_other", "error", "vpls: holds 16 VPLs, bake.json says 17",
              bake_json=manifest_with(vpls=dict(manifest["vpls"], count=17)))
    # Numbers in range that bounce-bake could not have written for this scene and these files
    # (engine/bake_folder/manifest_rules.h): the VPL clamp against its rule sqrt(A/(pi N)) (1e-45
    # drew the unclamped singularities), the settings against their hash, the VPL cap, error
    # targets and path count against the settings and the vpls file, the samples' mean.
    for name, r in (("1e_45", 1e-45), ("0", 0.0), ("doubled", 2 * manifest["vpls"]["clampDistance"])):
        bake_case("manifest_clamp_" + name, "error", "\"vpls.clampDistance\" is %s m, the bake's rule sqrt(A/(pi N)) gives 0.402912 m" % ("%g" % r),
                  bake_json=manifest_with(vpls=dict(manifest["vpls"], clampDistance=r)))
    bake_case("manifest_settings_seed_unhashed", "error", "\"settingsHash\" is %s, the settings hash to" % manifest["settingsHash"],
              bake_json=manifest_with(settings=dict(manifest["settings"], seed=7)))
    bake_case("manifest_vpl_cap_other", "error", "\"vpls.cap\" is 4096, the bake's settings.vpls is 16",
              bake_json=manifest_with(vpls=dict(manifest["vpls"], cap=4096)))
    bake_case("manifest_vpl_error_target_other", "error", "\"vpls.errorTarget\" is 0.5, the bake's settings.vplError is 0.01",
              bake_json=manifest_with(vpls=dict(manifest["vpls"], errorTarget=0.5)))
    bake_case("manifest_vpl_paths_fewer", "error", "\"vpls.paths\" is 52, fewer than the 53 paths",
              bake_json=manifest_with(vpls=dict(manifest["vpls"], paths=52)))
    bake_case("manifest_vpl_paths_more", "error", "\"vpls.paths\" is 5300, the vpls file's flux and vpls.relativeError 0.253008 give 53 paths",
              bake_json=manifest_with(vpls=dict(manifest["vpls"], paths=5300)))
    bake_case("manifest_vpl_relative_error_other", "error", "\"vpls.paths\" is 53, the vpls file's flux and vpls.relativeError 0.5 give",
              bake_json=manifest_with(vpls=dict(manifest["vpls"], relativeError=0.5)))
    bake_case("manifest_error_target_other", "error", "\"estimatedError.target\" is 1e-09, the bake's settings.targetError is 0.1",
              bake_json=manifest_with(estimatedError=dict(manifest["estimatedError"], target=1e-9)))
    bake_case("manifest_error_p95_other", "error", "\"estimatedError.p95\" is 0.123456, not the estimate of any texel of error.exr",
              bake_json=manifest_with(estimatedError=dict(manifest["estimatedError"], p95=0.123456)))
    bake_case("manifest_error_mean_over", "error", "\"estimatedError.mean\" is 1000, outside error.exr's estimates",
              bake_json=manifest_with(estimatedError=dict(manifest["estimatedError"], mean=1000.0)))
    bake_case("manifest_samples_mean_other", "error", "\"samples.perTexelMean\" is 1e+06, samples.total / (covered - invalid texels) is 16",
              bake_json=manifest_with(samples=dict(manifest["samples"], perTexelMean=1e6)))
    bake_case("manifest_samples_min_over_mean", "error", "\"samples.perTexelMean\" is 16, outside perTexelMin 17 .. perTexelMax 16",
              bake_json=manifest_with(samples=dict(manifest["samples"], perTexelMin=17)))
    bake_case("manifest_other_scene", "error", "stale bake: it does not match the scene (every part's hash matches", bake_json=manifest_with(sceneHash="0123456789abcdef"))
    bake_case("manifest_hash_number", "error", "no string \"sceneHash\"", bake_json=manifest_with(sceneHash=12))
    bake_case("layout_missing", "error", "layout.bin: missing", layout_bin=None)
    bake_case("layout_empty", "error", "layout.bin: truncated", layout_bin=b"")
    bake_case("layout_bad_magic", "error", "bad magic: not a bounce lightmap layout", layout_bin=b"BNCLMLAX" + layout[8:])
    bake_case("layout_version_9", "error", "layout.bin: format version 9", layout_bin=layout_with(8, "<I", 9))
    bake_case("layout_cut", "error", "layout.bin: truncated", layout_bin=layout[:len(layout) // 2])
    bake_case("layout_trailing", "error", "4 bytes after the last instance region", layout_bin=layout + b"\0\0\0\0")
    bake_case("layout_width_zero", "error", "atlas size 0x", layout_bin=layout_with(12, "<i", 0))
    bake_case("layout_texel_nan", "error", "texel size nan m is not positive", layout_bin=layout_with(20, "<f", float("nan")))
    bake_case("layout_region_count_huge", "error", "instance regions announced", layout_bin=layout_with(36, "<I", 0xFFFFFFF0))
    bake_case("layout_instance_out_of_range", "error", "out of range (the scene has 3 instances)", layout_bin=layout_with(40, "<I", 7))
    bake_case("layout_corner_nan", "error", "outside [0, 1]", layout_bin=layout_with(48, "<f", float("inf")))
    # Atlas UVs lie in [0, 1]: one flipped exponent byte, and 1e30 (an undefined float-to-int cast).
    flipped = bytearray(layout)
    flipped[51] ^= 0x40
    bake_case("layout_corner_byte_flipped", "error", "outside [0, 1]", layout_bin=bytes(flipped))
    bake_case("layout_corner_1e30", "error", "outside [0, 1]", layout_bin=layout_with(52, "<f", 1e30))
    # The last region left out: the count says one fewer and its bytes are gone.
    regions = struct.unpack_from("<I", layout, 36)[0]
    at = 40
    for r in range(regions - 1):
        at += 8 + 8 * struct.unpack_from("<I", layout, at + 4)[0]
    fewer = bytearray(layout[:at])
    struct.pack_into("<I", fewer, 36, regions - 1)
    bake_case("layout_region_missing", "error", "layout.bin: has %d instance regions, bake.json's atlas has %d" % (regions - 1, regions),
              layout_bin=bytes(fewer))
    # Any edit, stamped by no one, is caught by the hash: a flipped byte, two regions' first
    # corners swapped (same size, every range kept), an all-black lightmap.
    bake_case("layout_byte_flipped_unstamped", "error", "layout.bin: its hash is", stamp=False, layout_bin=bytes(flipped))
    swapped = bytearray(layout)
    swapped[48:56], swapped[104:112] = layout[104:112], layout[48:56]
    bake_case("layout_regions_swapped", "error", "layout.bin: its hash is", stamp=False, layout_bin=bytes(swapped))
    bake_case("lightmap_missing", "error", "lightmap.exr: missing", lightmap_exr=None)
    bake_case("lightmap_not_exr", "error", "lightmap.exr: cannot read EXR: not an OpenEXR file", lightmap_exr=b"P6\n2 2\n255\n" + b"\0" * 12)
    bake_case("lightmap_wrong_size", "error", "lightmap.exr: is 2x2, layout.bin says", lightmap_exr=exr(2, 2))
    # Irradiance the renderer would draw: one bad texel (3, 1) of a map of the layout's size.
    width, height = struct.unpack_from("<ii", layout, 12)
    for label, bad in (("nan", float("nan")), ("inf", float("inf")), ("negative", -1.0), ("3e38", 3e38)):
        bake_case("lightmap_texel_" + label, "error", "lightmap.exr: texel (3, 1) holds irradiance",
                  lightmap_exr=exr(width, height, values=lambda x, y, c, bad=bad: bad if (x, y, c) == (3, 1, 1) else 0.5))
    black = exr(width, height, values=lambda x, y, c: 0.0)
    bake_case("lightmap_black_unstamped", "error", "lightmap.exr: " + (
        "its hash is" if len(black) == len(bake_file("lightmap.exr")) else "%d bytes, bake.json records" % len(black)),
        stamp=False, lightmap_exr=black)
    # The layout, lightmap and VPLs of another bake (twice the atlas width, other VPLs): refused
    # by their hashes, and, re-recorded, by the atlas size bake.json gives.
    other_layout = layout_with(12, "<i", 2 * width)
    other_vpls = vpls_with(16, "<f", 0.125)
    other_map = exr(2 * width, height, values=lambda x, y, c: 0.25)
    bake_case("other_bakes_files_unstamped", "error", "layout.bin: ", stamp=False,
              layout_bin=other_layout, lightmap_exr=other_map, vpls=other_vpls)
    bake_case("other_bakes_files", "error", "layout.bin: is %dx%d, bake.json's atlas is %dx%d: another bake's" % (2 * width, height, width, height),
              layout_bin=other_layout, lightmap_exr=other_map, vpls=other_vpls)
    bake_case("error_map_unrecorded", "error", "error.exr: not recorded in bake.json's \"files\"", stamp=False, error_exr=bake_file("error.exr"),
              bake_json=manifest_with(files={k: v for k, v in manifest["files"].items() if k != "error.exr"}))
    bake_case("vpls_bad_magic", "error", "vpls: bad magic", vpls=b"BNCVPLX\0" + vpls[8:])
    bake_case("vpls_version_3", "error", "vpls: format version 3", vpls=vpls_with(8, "<I", 3))
    bake_case("vpls_count_mismatch", "error", "VPLs announced need", vpls=vpls_with(12, "<I", 1000))
    bake_case("vpls_position_nan", "error", "position is not finite", vpls=vpls_with(16, "<f", float("nan")))
    bake_case("vpls_normal_long", "error", "normal is not a unit vector", vpls=vpls_with(28, "<3f", 0.0, 2.0, 0.0))
    bake_case("vpls_flux_negative", "error", "flux is negative or not finite", vpls=vpls_with(40, "<f", -1.0))
    bake_case("vpls_flux_3e38", "error", "VPL 0: flux is over 1e+09 W", vpls=vpls_with(40, "<f", 3e38))
    bake_case("vpls_position_1e30", "error", "VPL 0: position is not finite or beyond 1e+06 m", vpls=vpls_with(16, "<f", 1e30))
    bake_case("vpls_flipped_unstamped", "error", "vpls: its hash is", stamp=False, vpls=vpls_with(40, "<f", 0.0))
    bake_case("vpls_cut", "error", "vpls: truncated", vpls=vpls[:10])
    # Version 2 (per VPL 52 bytes: ... flux at 40, from at 52, path index at 64).
    bake_case("vpls_version_1", "error", "format version 1, this build reads version 2: rebake",
              vpls=vpls_with(8, "<I", 1))
    bake_case("vpls_from_nan", "error", "path segment start is not finite",
              vpls=vpls_with(56, "<f", float("nan")))
    bake_case("vpls_path_decreasing", "error", "is smaller than the previous VPL's",
              vpls=vpls_with(64, "<I", 0xFFFFFFFF))
    # visibility.bin (docs/bake_folder.md): header 28 bytes (magic, version at 8, width 12,
    # height 16, area light count L at 20, punctual light count P at 24), then per texel
    # 4 x u16 light, 4 x f32 V (24 bytes). The scene has L = 1 static area light (the panel) and
    # P = 1 point light (index 1). Texel 0's slot 0 is at 28, its V at 36.
    def vis_with(offset, fmt, *values):
        b = bytearray(vis)
        struct.pack_into(fmt, b, offset, *values)
        return bytes(b)

    def vis_texel(width, height):  # a well-formed file of another size: every slot empty, V = 1
        return (b"BNCVISIB" + struct.pack("<IiiII", 2, width, height, 1, 1) +
                (struct.pack("<4H", *[0xFFFF] * 4) + struct.pack("<4f", *[1.0] * 4)) * (width * height))

    bake_case("visibility_bad_magic", "error", "visibility.bin: bad magic: not a bounce visibility file",
              visibility_bin=b"BNCVISIX" + vis[8:])
    bake_case("visibility_version_9", "error", "visibility.bin: format version 9, this build reads version 2: rebake",
              visibility_bin=vis_with(8, "<I", 9))
    bake_case("visibility_version_1", "error", "visibility.bin: format version 1, this build reads version 2: rebake",
              visibility_bin=vis_with(8, "<I", 1))
    bake_case("visibility_header_cut", "error", "visibility.bin: truncated: 10 bytes, the header needs 28",
              visibility_bin=vis[:10])
    bake_case("visibility_cut", "error", "visibility.bin: %dx%d texels need %d bytes, the file has %d" % (struct.unpack_from("<ii", vis, 12) + (len(vis), len(vis) - 24)),
              visibility_bin=vis[:-24])
    bake_case("visibility_trailing", "error", "visibility.bin: %dx%d texels need %d bytes, the file has %d" % (struct.unpack_from("<ii", vis, 12) + (len(vis), len(vis) + 1)),
              visibility_bin=vis + b"\0")
    bake_case("visibility_other_size", "error", "visibility.bin: is 2x2, layout.bin says %dx%d" % struct.unpack_from("<ii", layout, 12),
              visibility_bin=vis_texel(2, 2))
    bake_case("visibility_light_out_of_range", "error", "visibility.bin: texel 0: light 2 of 2",
              visibility_bin=vis_with(28, "<H", 2))
    bake_case("visibility_light_twice", "error", "visibility.bin: texel 0: names light 0 twice",
              visibility_bin=vis_with(28, "<2H2f", 0, 0, 0.5, 0.5))
    for name, v in (("nan", float("nan")), ("1_5", 1.5), ("negative", -0.1)):
        bake_case("visibility_v_" + name, "error", "visibility.bin: texel 0: visible fraction is not in [0, 1]",
                  visibility_bin=vis_with(36, "<f", v))
    bake_case("visibility_light_count_2", "error", "visibility.bin: holds 2 static area lights, ",
              visibility_bin=vis_with(20, "<I", 2))
    bake_case("visibility_punctual_count_3", "error", "visibility.bin: holds 3 punctual lights, ",
              visibility_bin=vis_with(24, "<I", 3))
    bake_case("visibility_lights_over_65533", "error", "visibility.bin: 1 area and 65533 punctual lights: at most 65533 in all",
              visibility_bin=vis_with(24, "<I", 65533))
    # Seeds of fuzz_bake (tests/fuzz/fuzz_bake.cpp): a byte picking the file, then its content.
    for i, f in enumerate(BAKE_FILES):
        write("bake_fuzz_seeds/valid_%s" % f.replace(".", "_"), bytes([i]) + bake_file(f), None, None)
    for name, i, f in (("layout_cut", 1, "layout.bin"), ("vpls_normal_long", 3, "vpls"),
                       ("manifest_other_scene", 0, "bake.json"),
                       ("visibility_light_twice", 4, "visibility.bin")):
        with open(os.path.join(ROOT, "bake", name + ".bake", f), "rb") as src:
            write("bake_fuzz_seeds/%s" % name, bytes([i]) + src.read(), None, None)
else:
    print("bake/valid.bake is missing: bake it first (command above); bake cases skipped")

# ---------------------------------------------------------------- found by fuzzing ----------
# Inputs the fuzz targets saved (docs/fuzzing.md), committed as they were found (not generated):
# the first four made bounce's readExr leak tinyexr's header (LoadEXRFromMemory) before the fix.
FOUND = [
    ("found/fuzz_exr_header_attribute.exr", "error", "cannot read EXR: Failed to read attribute"),
    ("found/fuzz_exr_corrupt_pixels.exr", "error", "cannot read EXR: Invalid data found when decoding pixels"),
    ("found/fuzz_exr_channel_info.exr", "error", "cannot read EXR: Failed to parse channel info"),
    ("found/fuzz_exr_data_width.exr", "error", "cannot read EXR: data window -4x8 has no pixels"),
    # tinyexr assert()ed (abort, no message) on its unknown `type` attribute "els\xa5chlist...".
    ("found/fuzz_exr_type_assert.exr", "error", "cannot read EXR: header attribute type"),
    # ... and on type "tiledimage" with the tiled bit but no `tiles` attribute (CI's 20 s run).
    ("found/fuzz_exr_tiledimage_assert.exr", "error", "header attribute type 'tiledimage'"),
    # Data windows 2x2516582404 and 4x2147483652: tinyexr resized its offset table to a negative
    # count, std::length_error naming no file (the long run, docs/fuzzing.md round 3).
    ("found/fuzz_exr_window_overflow_a.exr", "error", "data window 2x2516582404 exceeds"),
    ("found/fuzz_exr_window_overflow_b.exr", "error", "data window 4x2147483652 exceeds"),
    # tinyexr converts a header even when its parse failed part-way, and assert()ed on the
    # `type` read before the failure (round 4): now every `type` is renamed before tinyexr
    # parses, and bounce checks it over the attributes tinyexr would read.
    ("found/fuzz_exr_type_after_failed_attribute.exr", "error", "cannot read EXR: header attribute type 'tiledimage'"),
    ("found/fuzz_exr_type_unknown_kind.exr", "error", "cannot read EXR"),
    ("found/fuzz_exr_type_tiled_then_failed.exr", "error", "cannot read EXR: header attribute type 'tiledimage'"),
    # A `tiles` attribute with level mode 3: tinyexr assert()ed counting the levels (round 4b).
    ("found/fuzz_exr_tile_level_mode_a.exr", "error", "header attribute tiles has level mode 3"),
    ("found/fuzz_exr_tile_level_mode_b.exr", "error", "header attribute tiles has level mode 3"),
    # A vertex at x = 2e6 m after a lone "\r", which tinyobjloader reads as a line end: the
    # number check split lines at "\n" only, so the vertex passed as part of an 'f' line and the
    # scene broke the coordinate limit (CI's 20 s run of fuzz_obj).
    ("found/fuzz_obj_vertex_after_a_lone_cr.obj", "error", "line 9: '2e6' in 'v' is not a finite number within"),
]
rows.extend(FOUND)

rows.sort()
with open(os.path.join(ROOT, "manifest.tsv"), "w") as f:
    f.write("# file\texpect\tdetail   (generated by make_corpus.py; see its docstring)\n")
    for r in rows:
        f.write("\t".join(r) + "\n")
print("bounce corpus: %d manifest entries, %d files in its folders" % (
    len(rows), sum(len(fs) for d, _, fs in os.walk(ROOT) if d != ROOT)))
