// A JSON object's fields read with their checks: every failure is a LoadError naming the file
// and the field's dotted path ("atlas.width"). The bake folder's readers share it (bake.json,
// bake_settings.h). GL-free.
#pragma once

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "io/load_error.h"

namespace bounce {

// A number in a refusal: "1e+09", "0.5" (printf's %g); bake_manifest.cpp.
std::string shortNumber(double value);

// Reads one object's fields (see above).
class JsonFields {
 public:
  JsonFields(const std::filesystem::path& file, const nlohmann::json& object, std::string path)
      : file_(file), object_(object), path_(std::move(path)) {}

  [[noreturn]] void fail(const std::string& why) const { throw LoadError(file_, why); }
  std::string name(const char* key) const { return path_.empty() ? key : path_ + "." + key; }
  // "\"atlas.width\"", built by appends (GCC 12 warns falsely on `"\"" + string`).
  std::string quoted(const std::string& name) const {
    std::string q(1, '"');
    q.append(name).push_back('"');
    return q;
  }

  const nlohmann::json* find(const char* key) const {
    const auto it = object_.find(key);
    return it == object_.end() ? nullptr : &*it;
  }
  const nlohmann::json& need(const char* key, bool ok, const char* kind) const {
    const nlohmann::json* v = find(key);
    if (v == nullptr || !ok) fail(std::string("no ").append(kind).append(" ") + quoted(name(key)));
    return *v;
  }
  JsonFields object(const char* key) const {
    const nlohmann::json* v = find(key);
    return {file_, need(key, v && v->is_object(), "object"), name(key)};
  }
  // An exact integer in [lo, hi]: 1.0, 2^32+1 for an int, or -1 for a count are refused.
  int64_t integer(const char* key, int64_t lo, int64_t hi) const {
    const nlohmann::json* v = find(key);
    const nlohmann::json& j = need(key, v && v->is_number_integer(), "integer");
    const bool tooBig =
        j.is_number_unsigned() &&
        j.get<uint64_t>() > static_cast<uint64_t>(std::numeric_limits<int64_t>::max());
    const int64_t value = tooBig ? hi : j.get<int64_t>();
    if (tooBig || value < lo || value > hi)
      fail(quoted(name(key)) + " is " + j.dump() + ", out of range " + std::to_string(lo) + ".." +
           std::to_string(hi));
    return value;
  }
  uint64_t count(const char* key) const {
    return static_cast<uint64_t>(integer(key, 0, std::numeric_limits<int64_t>::max()));
  }
  double real(const char* key, double lo = 0.0,
              double hi = std::numeric_limits<double>::max()) const {
    const nlohmann::json* v = find(key);
    const double value = need(key, v && v->is_number(), "number").get<double>();
    if (!(value >= lo && value <= hi))
      fail(quoted(name(key)) + " is " + shortNumber(value) + ", out of range [" + shortNumber(lo) +
           ", " + shortNumber(hi) + "]");
    return value;
  }
  std::string text(const char* key) const {
    const nlohmann::json* v = find(key);
    return need(key, v && v->is_string(), "string").get<std::string>();
  }
  bool boolean(const char* key) const {
    const nlohmann::json* v = find(key);
    return need(key, v && v->is_boolean(), "boolean").get<bool>();
  }
  std::vector<std::string> texts(const char* key) const {
    const nlohmann::json* v = find(key);
    std::vector<std::string> out;
    for (const nlohmann::json& s : need(key, v && v->is_array(), "array")) {
      if (!s.is_string()) fail(quoted(name(key)) + " holds a non-string");
      out.push_back(s.get<std::string>());
    }
    return out;
  }
  glm::dvec3 rgb(const nlohmann::json& j, const std::string& what) const {
    if (!j.is_array() || j.size() != 3) fail(quoted(what) + " is not an RGB triple");
    glm::dvec3 c;
    for (int k = 0; k < 3; ++k) {
      if (!j[k].is_number() || !std::isfinite(j[k].get<double>()) || j[k].get<double>() < 0.0)
        fail(quoted(what) + " holds a value that is not a finite non-negative number");
      c[k] = j[k].get<double>();
    }
    return c;
  }
  const nlohmann::json& json() const { return object_; }

 private:
  const std::filesystem::path& file_;
  const nlohmann::json& object_;
  std::string path_;
};

}  // namespace bounce
