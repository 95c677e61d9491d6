#include "scene/gltf_schema.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

#include "io/json_depth.h"
#include "io/load_error.h"

namespace bounce {
namespace {

using Json = nlohmann::json;

// Walks the document along the properties bounce reads; `where` is the JSON path of the value
// in messages ("nodes[3].translation").
class SchemaCheck {
 public:
  explicit SchemaCheck(const std::filesystem::path& file) : file_(file) {}

  void document(const Json& root) {
    if (!root.is_object()) fail("the document", "must be a JSON object");
    asset(root);
    stringArray(root, "extensionsUsed", "");
    stringArray(root, "extensionsRequired", "");
    index(root, "scene", "");
    each(root, "scenes", [&](const Json& s, const std::string& w) { indexArray(s, "nodes", w); });
    each(root, "nodes", [&](const Json& n, const std::string& w) { node(n, w); });
    each(root, "meshes", [&](const Json& m, const std::string& w) { mesh(m, w); });
    each(root, "accessors", [&](const Json& a, const std::string& w) { accessor(a, w); });
    each(root, "bufferViews", [&](const Json& v, const std::string& w) { bufferView(v, w); });
    each(root, "buffers", [&](const Json& b, const std::string& w) {
      integer(b, "byteLength", w, 1, true);
      string(b, "uri", w);
    });
    each(root, "materials", [&](const Json& m, const std::string& w) { material(m, w); });
    each(root, "textures", [&](const Json& t, const std::string& w) {
      index(t, "source", w);
      index(t, "sampler", w);
    });
    each(root, "images", [&](const Json& i, const std::string& w) {
      string(i, "uri", w);
      string(i, "mimeType", w);
      index(i, "bufferView", w);
    });
    each(root, "cameras", [&](const Json& c, const std::string& w) { camera(c, w); });
    if (const Json* lights = member(root, "extensions", "")) {
      if (const Json* punctual = objectMember(*lights, "KHR_lights_punctual", "extensions"))
        each(
            *punctual, "lights", [&](const Json& l, const std::string& w) { light(l, w); },
            "extensions.KHR_lights_punctual");
    }
  }

 private:
  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw LoadError(file_, where + " " + what);
  }

  static std::string join(const std::string& where, const std::string& key) {
    return where.empty() ? key : where + "." + key;
  }

  // The member `key` of object `o`, or nullptr when absent. JSON null counts as present (and
  // then fails its type check): `primitives: null` is not "no primitives".
  const Json* member(const Json& o, const std::string& key, const std::string&) const {
    const auto it = o.find(key);
    return it == o.end() ? nullptr : &*it;
  }
  const Json* objectMember(const Json& o, const std::string& key, const std::string& where) const {
    const Json* v = member(o, key, where);
    if (v && !v->is_object()) fail(join(where, key), "must be a JSON object");
    return v;
  }

  template <typename F>
  void each(const Json& o, const std::string& key, F&& check, const std::string& where = "") {
    const Json* array = member(o, key, where);
    if (!array) return;
    const std::string w = join(where, key);
    if (!array->is_array()) fail(w, "must be an array");
    for (std::size_t i = 0; i < array->size(); ++i) {
      const std::string wi = w + "[" + std::to_string(i) + "]";
      if (!(*array)[i].is_object()) fail(wi, "must be a JSON object");
      check((*array)[i], wi);
    }
  }

  void integer(const Json& o, const std::string& key, const std::string& where, int64_t min,
               bool required = false, int64_t max = INT32_MAX) const {
    const Json* v = member(o, key, where);
    if (!v) {
      if (required) fail(join(where, key), "is required");
      return;
    }
    if (!v->is_number_integer())
      fail(join(where, key), "must be an integer (the file has " + v->dump(-1).substr(0, 40) + ")");
    const auto x = v->get<int64_t>();
    if (x < min || x > max || (v->is_number_unsigned() && v->get<uint64_t>() > INT64_MAX)) {
      fail(join(where, key), "must be in " + std::to_string(min) + ".." + std::to_string(max) +
                                 " (the file has " + v->dump() + ")");
    }
  }
  void index(const Json& o, const std::string& key, const std::string& where,
             bool required = false) const {
    integer(o, key, where, 0, required);
  }

  void indexArray(const Json& o, const std::string& key, const std::string& where) const {
    const Json* v = member(o, key, where);
    if (!v) return;
    if (!v->is_array()) fail(join(where, key), "must be an array of indices");
    for (const Json& x : *v) {
      if (!x.is_number_integer() || x.get<int64_t>() < 0 || x.get<int64_t>() > INT32_MAX)
        fail(join(where, key), "must hold non-negative integer indices only");
    }
  }

  void number(const Json& o, const std::string& key, const std::string& where, double min,
              double max, bool required = false) const {
    const Json* v = member(o, key, where);
    if (!v) {
      if (required) fail(join(where, key), "is required");
      return;
    }
    if (!v->is_number())
      fail(join(where, key), "must be a number (the file has " + v->dump(-1).substr(0, 40) + ")");
    const auto x = v->get<double>();
    if (!std::isfinite(x) || x < min || x > max) {
      fail(join(where, key), "must be a finite number in [" + std::to_string(min) + ", " +
                                 std::to_string(max) + "] (the file has " + v->dump() + ")");
    }
  }

  // An array of exactly `n` finite numbers (n = 0: any length ≥ 1).
  void numbers(const Json& o, const std::string& key, const std::string& where, std::size_t n,
               double min = -INFINITY, double max = INFINITY) const {
    const Json* v = member(o, key, where);
    if (!v) return;
    const std::string w = join(where, key);
    const std::string want =
        "must be an array of " + std::to_string(n) + " finite numbers" +
        (std::isfinite(min) ? " in [" + std::to_string(min) + ", " + std::to_string(max) + "]"
                            : std::string());
    if (!v->is_array() || v->size() != n) fail(w, want);
    for (const Json& x : *v)
      if (!x.is_number() || !std::isfinite(x.get<double>()) || x.get<double>() < min ||
          x.get<double>() > max)
        fail(w, want + " (the file has " + v->dump(-1).substr(0, 60) + ")");
  }

  void string(const Json& o, const std::string& key, const std::string& where,
              bool required = false) const {
    const Json* v = member(o, key, where);
    if (!v) {
      if (required) fail(join(where, key), "is required");
      return;
    }
    if (!v->is_string()) fail(join(where, key), "must be a string");
  }

  void boolean(const Json& o, const std::string& key, const std::string& where) const {
    const Json* v = member(o, key, where);
    if (v && !v->is_boolean()) fail(join(where, key), "must be true or false");
  }

  void stringArray(const Json& o, const std::string& key, const std::string& where) const {
    const Json* v = member(o, key, where);
    if (!v) return;
    if (!v->is_array()) fail(join(where, key), "must be an array of strings");
    for (const Json& x : *v)
      if (!x.is_string()) fail(join(where, key), "must be an array of strings");
  }

  void asset(const Json& root) const {
    const Json* a = objectMember(root, "asset", "");
    if (!a) fail("asset", "is required");
    string(*a, "version", "asset", true);
    // glTF 2.0 §3.3: a loader rejects a major version it does not support. Accepted: "2.<n>".
    const std::string version = (*a)["version"].get<std::string>();
    const bool two = version.size() > 2 && version.compare(0, 2, "2.") == 0 &&
                     version.find_first_not_of("0123456789", 2) == std::string::npos;
    if (!two) fail("asset.version", "is \"" + version + "\"; bounce reads glTF 2.x");
    string(*a, "minVersion", "asset");
    if (const Json* mv = member(*a, "minVersion", "asset"); mv && mv->get<std::string>() != "2.0")
      fail("asset.minVersion", "is \"" + mv->get<std::string>() + "\"; bounce reads glTF 2.0");
  }

  void node(const Json& n, const std::string& w) const {
    index(n, "camera", w);
    index(n, "mesh", w);
    index(n, "skin", w);
    indexArray(n, "children", w);
    numbers(n, "matrix", w, 16);
    numbers(n, "translation", w, 3);
    numbers(n, "rotation", w, 4);
    numbers(n, "scale", w, 3);
    string(n, "name", w);
    if (const Json* ext = objectMember(n, "extensions", w))
      if (const Json* l = objectMember(*ext, "KHR_lights_punctual", join(w, "extensions")))
        index(*l, "light", join(w, "extensions.KHR_lights_punctual"), true);
  }

  void mesh(const Json& m, const std::string& w) {
    const Json* prims = member(m, "primitives", w);
    if (!prims) fail(join(w, "primitives"), "is required");
    if (!prims->is_array() || prims->empty())
      fail(join(w, "primitives"), "must be a non-empty array");
    each(
        m, "primitives",
        [&](const Json& p, const std::string& pw) {
          const Json* attributes = objectMember(p, "attributes", pw);
          if (!attributes) fail(join(pw, "attributes"), "is required");
          for (const auto& [name, value] : attributes->items())
            index(*attributes, name, join(pw, "attributes"));
          index(p, "indices", pw);
          index(p, "material", pw);
          integer(p, "mode", pw, 0, false, 6);
        },
        w);
  }

  void accessor(const Json& a, const std::string& w) const {
    index(a, "bufferView", w);
    integer(a, "byteOffset", w, 0);
    integer(a, "componentType", w, 5120, true, 5126);
    boolean(a, "normalized", w);
    integer(a, "count", w, 1, true);
    string(a, "type", w, true);
    if (member(a, "sparse", w)) objectMember(a, "sparse", w);
  }

  void bufferView(const Json& v, const std::string& w) const {
    index(v, "buffer", w, true);
    integer(v, "byteOffset", w, 0);
    integer(v, "byteLength", w, 1, true);
    integer(v, "byteStride", w, 4, false, 252);
  }

  void textureInfo(const Json& o, const std::string& key, const std::string& where) const {
    if (const Json* t = objectMember(o, key, where)) {
      index(*t, "index", join(where, key), true);
      index(*t, "texCoord", join(where, key));
    }
  }

  void material(const Json& m, const std::string& w) const {
    if (const Json* pbr = objectMember(m, "pbrMetallicRoughness", w)) {
      const std::string pw = join(w, "pbrMetallicRoughness");
      numbers(*pbr, "baseColorFactor", pw, 4, 0.0, 1.0);
      textureInfo(*pbr, "baseColorTexture", pw);
    }
    numbers(m, "emissiveFactor", w, 3, 0.0, 1.0);
    textureInfo(m, "emissiveTexture", w);
    boolean(m, "doubleSided", w);
    string(m, "name", w);
    if (const Json* ext = objectMember(m, "extensions", w))
      if (const Json* s =
              objectMember(*ext, "KHR_materials_emissive_strength", join(w, "extensions")))
        number(*s, "emissiveStrength", join(w, "extensions.KHR_materials_emissive_strength"), 0.0,
               INFINITY);
  }

  void camera(const Json& c, const std::string& w) const {
    string(c, "type", w, true);
    if (const Json* p = objectMember(c, "perspective", w)) {
      const std::string pw = join(w, "perspective");
      number(*p, "yfov", pw, 0.0, INFINITY, true);
      number(*p, "znear", pw, 0.0, INFINITY, true);
      number(*p, "zfar", pw, 0.0, INFINITY);
      number(*p, "aspectRatio", pw, 0.0, INFINITY);
    }
  }

  void light(const Json& l, const std::string& w) const {
    string(l, "type", w, true);
    numbers(l, "color", w, 3, 0.0, INFINITY);
    number(l, "intensity", w, 0.0, INFINITY);
    number(l, "range", w, 0.0, INFINITY);
    if (const Json* s = objectMember(l, "spot", w)) {
      number(*s, "innerConeAngle", join(w, "spot"), 0.0, INFINITY);
      number(*s, "outerConeAngle", join(w, "spot"), 0.0, INFINITY);
    }
  }

  std::filesystem::path file_;
};

}  // namespace

void checkGltfSchema(const std::filesystem::path& file, std::string_view json) {
  checkJsonDepth(file, json);
  const Json root = Json::parse(json.begin(), json.end(), nullptr, /*allow_exceptions=*/false);
  if (root.is_discarded()) throw LoadError(file, "invalid glTF: not valid JSON");
  SchemaCheck(file).document(root);
}

}  // namespace bounce
