// The bake a tool uses when none is named (bounce-render, bounce-view): the first of
//   1. <scene without its extension>.bake beside the scene (bounce-bake's default output),
//   2. <tools>/../content/<the scene's folder>/<scene stem>.bake (the build step's bake of a
//      content scene, content/CMakeLists.txt)
// that exists. A folder that exists but cannot be used (stale, another format, damaged) is
// passed over with a note saying why, so the tool draws the scene without baked light rather
// than stopping. GL-free.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bake_folder/bake_folder.h"

namespace bounce {

// A folder found for the scene but not used, and why.
struct RefusedBake {
  enum class Reason {
    Stale,     // made for another version of the scene (StaleBakeError): a re-bake fixes it
    Unusable,  // missing files, damaged, another format: readBake's reason says which
  };
  std::filesystem::path dir;
  Reason reason = Reason::Unusable;
  std::string why;  // readBake's message
};

struct BakeSearch {
  std::optional<Bake> bake;
  std::filesystem::path dir;         // the folder read; empty when none was usable
  std::vector<RefusedBake> refused;  // the folders passed over, in search order
  std::vector<std::string> notes;    // one line each: what was used, or why a folder was not
  // Whether the scene's bake exists but no longer matches it (the viewer's "lighting needs to
  // be rebuilt"): a folder was passed over as stale and none was used.
  bool stale() const;
};

// The folder of the running executable (from /proc/self/exe); empty when it cannot be read.
std::filesystem::path toolDirectory();

// The places above, in order (they need not exist).
std::vector<std::filesystem::path> bakeCandidates(const std::filesystem::path& scenePath,
                                                  const std::filesystem::path& toolDir);

BakeSearch findSceneBake(const std::filesystem::path& scenePath, const Scene& scene,
                         const std::filesystem::path& toolDir);

}  // namespace bounce
