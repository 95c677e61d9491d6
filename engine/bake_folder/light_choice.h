// How next-event estimation picks its one light per vertex (baker/trace/light_sampler.h), and
// its one name in files and options: "place" or "power". GL-free, header only: the path tracer
// and the bake folder's settings (bake_settings.h) share it.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace bounce {

enum class LightChoice : uint8_t {
  ByPlace,  // by a bound of what each light brings to the vertex (the default)
  ByPower,  // by power alone, wherever the vertex is
};

inline const char* lightChoiceName(LightChoice choice) {
  return choice == LightChoice::ByPlace ? "place" : "power";
}

// "place" or "power"; none for anything else.
inline std::optional<LightChoice> parseLightChoice(std::string_view name) {
  if (name == "place") return LightChoice::ByPlace;
  if (name == "power") return LightChoice::ByPower;
  return std::nullopt;
}

}  // namespace bounce
