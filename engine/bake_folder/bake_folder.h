// The bake folder: what bounce-bake writes and the renderer reads, one versioned format with its
// reader and writer here. GL-free.
//
//   <dir>/bake.json       the manifest (bake_manifest.h): format version, scene hash and its
//                         parts (scene_hash.h), settings, atlas stats, samples, estimated error,
//                         ..., the size and hash of every other file, and under "measured" what
//                         varies from run to run (times, rays per second, peak memory)
//   <dir>/lightmap.exr    irradiance E in W/m² per linear-RGB channel, one texel per atlas texel,
//                         rows top first (see lightmap_layout.h)
//   <dir>/layout.bin      the LightmapLayout (versioned binary)
//   <dir>/vpls            the virtual point lights (optional; engine/bake_folder/vpl_file.h)
//   <dir>/visibility.bin  the static area lights' visibility per texel (optional;
//                         engine/bake_folder/visibility_file.h, bake_folder/light_visibility.h)
//   <dir>/probes.bin      the irradiance probes of the static instances without a lightmap
//                         region (optional; engine/bake_folder/probe_file.h, irradiance_probes.h)
//   <dir>/error.exr       per texel, the estimated relative standard error of its irradiance
//                         (dimensionless, the same in R, G and B; -1 where the texel has no
//                         estimate of its own: uncovered, or filled from its neighbours)
//                         (optional; the renderer's --mode error shows it)
//
// A folder is written whole or not at all: into "<dir>.tmp-<pid>", then renamed over <dir>, so
// an interrupted bake leaves the previous one intact.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bake_folder/bake_manifest.h"
#include "bake_folder/irradiance_probes.h"
#include "bake_folder/light_visibility.h"
#include "bake_folder/lightmap_layout.h"
#include "bake_folder/scene_hash.h"
#include "bake_folder/vpl.h"
#include "image/image.h"
#include "io/load_error.h"
#include "scene/scene.h"

namespace bounce {

struct Bake {
  LightmapLayout layout;
  Image irradiance;  // W/m², layout.width × layout.height
  // bake.json; writeBake fills `files`. Its "atlas" size and "regions" are the layout's, its
  // "vpls" and "visibility" are present exactly when those files are (and agree with them).
  BakeManifest manifest;
  // The VPLs (written to and read from <dir>/vpls when present).
  std::optional<std::vector<Vpl>> vpls;
  // The static area lights' baked visibility (<dir>/visibility.bin when present).
  std::optional<BakedVisibility> visibility;
  // The irradiance probes of the static instances without an atlas region (<dir>/probes.bin when
  // present): a grid for each, no other instance's.
  std::optional<IrradianceProbes> probes;
  // Per texel the estimated relative standard error of E, or kNoErrorEstimate (<dir>/error.exr
  // when present).
  std::optional<Image> relativeError;
};

inline constexpr float kNoErrorEstimate = -1.0f;
inline constexpr float kMaxRelativeError = 1e6f;  // what a reader accepts

// What readBake throws when the bake was made for another scene (its "sceneHash" differs from
// the scene's): rebaking fixes it. A LoadError, so callers that do not ask keep working.
class StaleBakeError : public LoadError {
 public:
  using LoadError::LoadError;
};

// Reads <dir>; throws LoadError naming the folder or its file and the reason when a file is
// missing or malformed, when the format version is not kBakeFormatVersion, when the bake is
// stale (its "sceneHash" differs from sceneContentHash(scene); the message gives both hashes and
// why, where bake.json tells: another scene file ("scene"), which parts changed ("sceneParts",
// scene_hash.h), or a scene file modified after bake.json), when a file's size or hash is not
// the one bake.json records (damaged, or another bake's), when a file disagrees with the
// manifest (atlas size, regions, VPL count, visibility lights, probe count), when a probe grid
// names an instance that is not static or has a lightmap region, and when a value is out of its
// documented range (docs/bake_folder.md: irradiance finite in [0, kMaxBakeIrradiance], UVs in
// [0, 1], VPL flux and positions). A stale bake throws StaleBakeError.
Bake readBake(const std::filesystem::path& dir, const Scene& scene);

// Writes <dir> whole or not at all (see above), with bake.json's "files" set from the bytes
// written. bake.manifest must hold formatVersion = kBakeFormatVersion, a sceneHash and agree with
// the files as readBake requires; throws std::runtime_error naming the folder and the reason
// otherwise, or when a write fails.
void writeBake(const std::filesystem::path& dir, const Bake& bake);

}  // namespace bounce
