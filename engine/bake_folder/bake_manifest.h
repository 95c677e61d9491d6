// bake.json as one typed struct: what bounce-bake wrote about a bake (settings, atlas, samples,
// error, leaks, seams, rays, VPLs, visibility, memory) and the size and hash of every other file
// of the folder. Only the bake-folder module (bake_folder.cpp) turns it into text and back:
// writeBake serialises it, readBake parses it, every other reader takes the struct. GL-free.
//
// Everything outside `measured` depends only on the scene, the settings and this build: two
// bakes with identical inputs write identical bake.json files but for "measured" (times, rays
// per second, the measured peak memory), so bake folders compare byte for byte once it is
// removed. Units: metres, W, W/m², bytes, seconds.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "bake_folder/bake_settings.h"

namespace bounce {

inline constexpr int kBakeFormatVersion = 2;

// The ranges a reader accepts (docs/bake_folder.md), far beyond any real scene yet small enough
// that the renderer's float arithmetic cannot overflow: lightmap irradiance per channel (W/m²),
// VPL flux per channel (W), VPL positions and the clamp distance (m, each coordinate).
inline constexpr float kMaxBakeIrradiance = 1e9f;
inline constexpr float kMaxVplFlux = 1e9f;
inline constexpr float kMaxBakeLength = 1e6f;

// One file of the folder as writeBake wrote it: its size and FNV-1a 64 of its bytes.
struct BakeFileRecord {
  uint64_t bytes = 0;
  std::string hash{};  // 16 lowercase hex digits
  bool operator==(const BakeFileRecord&) const = default;
};

// A number in a refusal: "1e+09", "0.5" (printf's %g).
std::string shortNumber(double value);

// FNV-1a 64 of `bytes`, 16 lowercase hex digits.
std::string fnv1a64Hex(std::span<const unsigned char> bytes);

struct BakeManifest {
  int formatVersion = kBakeFormatVersion;
  std::string sceneHash;                          // sceneContentHash of the scene baked
  std::map<std::string, std::string> sceneParts;  // scene_hash.h's parts, by name
  std::string scene;                              // the scene file's name (no folder)
  std::string settingsHash;                       // FNV-1a 64 of the settings' JSON

  // The settings as the bake resolved them: texelSize the atlas's, texelBudget 0 where a texel
  // size was given (bake_settings.h).
  BakeSettings settings;
  // Names of the lights and emissive materials whose direct light the map holds.
  std::vector<std::string> directBaked;
  struct Atlas {
    int width = 0, height = 0;  // texels: layout.bin's
    double texelSize = 0.0;     // m
    std::string texelRule{};
    double staticArea = 0.0, weightedArea = 0.0;  // m²
    int padding = 0, charts = 0;
    uint64_t regions = 0;          // layout.bin's instance regions
    uint64_t vplLitInstances = 0;  // static instances without a region (lit by the VPLs)
    double utilisation = 0.0;
    uint64_t coveredTexels = 0, invalidTexels = 0;
    std::vector<std::string> notes{};
  } atlas;
  struct Samples {
    uint64_t total = 0, perTexelMin = 0, perTexelMax = 0, nonFinite = 0;
    double perTexelMean = 0.0;
  } samples;
  struct EstimatedError {
    // The delivered map's relative error (after every filter; baker/bake/delivered_error.h):
    // mean and p95 over the lit texels with samples of their own, and Σ|error| / Σ E.
    double mean = 0.0, p95 = 0.0, luminanceWeighted = 0.0;
    double target = 0.0;  // the adaptive stop's target (of beforeFilters' per-texel figure)
    // Each texel's relative standard error from its own samples, before the filters (what the
    // adaptive stop compares with the target). Bakes before 2026-11-27 have only these, as
    // mean and p95 (0 here).
    double beforeFiltersMean = 0.0, beforeFiltersP95 = 0.0;
    // Lit texels whose error is not known (error.exr 1): filled from their neighbours after the
    // adaptive stop left them at 0; not in mean, p95 or luminanceWeighted.
    uint64_t unknownTexels = 0;
  } estimatedError;
  struct Leaks {
    uint64_t pointsInsideGeometry = 0, pointsAcrossWalls = 0, invalidTexelsFilled = 0;
  } leaks;
  struct Seams {
    uint64_t count = 0;
    double relativeMismatchAfterStitching = 0.0;
  } seams;
  struct Rays {
    uint64_t traced = 0;
    std::string backend{};
  } rays;
  // Present exactly when the folder has a vpls file.
  struct Vpls {
    uint64_t count = 0, paths = 0;
    glm::dvec3 totalFlux{0.0};                // W
    std::vector<glm::dvec3> fluxPerBounce{};  // W, to the deepest bounce with a VPL
    double relativeError = 0.0, errorTarget = 0.0;
    int64_t cap = 0;
    double clampDistance = 0.0;  // m, vpl_clamp.h; in [0, kMaxBakeLength]
  };
  std::optional<Vpls> vpls;
  // Present exactly when the folder has a visibility.bin.
  struct Visibility {
    uint64_t lights = 0, punctualLights = 0, slotsPerTexel = 0, samplesPerLight = 0,
             texelsReached = 0, texelsOverSlots = 0, rays = 0;
    double otherLightsShare = 0.0;
  };
  std::optional<Visibility> visibility;
  // Present exactly when the folder has a probes.bin (bake_folder/probe_file.h).
  struct Probes {
    uint64_t count = 0, grids = 0;
    // Probes inside geometry or behind a wall (most of their test rays met back faces), filled
    // from the valid probes of their grid.
    uint64_t invalidFilled = 0;
    // Grid points no surface of their instance can read: not sampled, stored as 0.
    uint64_t unread = 0;
    uint64_t samplesTotal = 0, samplesPerProbeMin = 0, samplesPerProbeMax = 0;
    double meanRelativeError = 0.0, targetError = 0.0;  // relative standard error of E(n)
    uint64_t leakTestRays = 0;  // rays of the inside-geometry test (not of the estimate)
  };
  std::optional<Probes> probes;

  // Run-dependent: differs between two bakes of identical inputs.
  struct Measured {
    struct Seconds {
      double load = 0.0, atlas = 0.0, rayKernel = 0.0, coverage = 0.0, leakGuard = 0.0,
             irradiance = 0.0, visibility = 0.0, denoise = 0.0, dilate = 0.0, stitch = 0.0,
             vpls = 0.0, probes = 0.0, total = 0.0;
    } seconds;
    double raysPerSecond = 0.0;
    double peakBytes = 0.0;  // the process's peak resident set at the end of the bake
    // bake_memory.h's estimate after the atlas: it depends on the thread count, not a setting.
    double estimatedPeakBytes = 0.0;
  } measured;

  // Every file of the folder but bake.json, by name; set by writeBake.
  std::map<std::string, BakeFileRecord> files;
};

// bake.json's text: deterministic (keys sorted, numbers in shortest round-trip form), one
// newline at the end.
std::string manifestText(const BakeManifest& manifest);

// Parses bake.json; throws LoadError(file, reason) for text that is not JSON, a field missing,
// of the wrong type or out of its range (integers exact and within their type, reals finite),
// and a formatVersion other than kBakeFormatVersion ("rebake").
BakeManifest parseManifest(const std::filesystem::path& file, const std::string& text);

}  // namespace bounce
