// How the lightmap's texels gather their indirect light (baker/bake/irradiance_cache.h,
// docs/baker.md "Gather with a cache"), and its one name in files and options: "paths" or
// "cache". GL-free, header only: the baker and the bake folder's settings (bake_settings.h)
// share it.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace bounce {

enum class Gather : uint8_t {
  Paths,  // every sample a whole path (next-event estimation at each vertex, Russian roulette)
  Cache,  // a short bake first, then paths that end at its map after one reflection
};

inline const char* gatherName(Gather gather) {
  return gather == Gather::Cache ? "cache" : "paths";
}

// "paths" or "cache"; none for anything else.
inline std::optional<Gather> parseGather(std::string_view name) {
  if (name == "paths") return Gather::Paths;
  if (name == "cache") return Gather::Cache;
  return std::nullopt;
}

}  // namespace bounce
