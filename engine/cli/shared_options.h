// The options several tools declare alike, declared once (CLI11): each add* call adds one group
// to an App and binds it to a field of SharedOptions, so the name, the check, the error for a
// bad value and the help are the same in every tool that takes it.
//
//   option                        bounce-render  bounce-view  bounce-trace  bounce-bake
//   scene (positional)                  x             x             x            x
//   --camera                            x             x             x
//   --width, --height                   x             x             x
//   --exposure                          x             x             x            x
//   --bake, --no-bake                   x             x
//   --mode                              x             x
//   --msaa                              x             x
//   --cost-count, --cost-max            x             x
//   --dynamic-vpls                      x             x
//   --max-depth, --seed, --threads,                                 x            x
//   --backend, --light-choice
//   --move (instance_move_option.h)     x             x             x
//
// A tool's own defaults (bounce-render's 512x512 image, bounce-view's 1280x720 window, the
// bake's settings) are the fields' values when the group is added: CLI11 leaves a field that is
// not given as it was. The groups only collect words and numbers; a tool turns the names (mode,
// backend, light choice) into its types after the parse (each is checked here against the names
// the tool accepts). GL-free, baker-free: the mode names come from the caller.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "bake_folder/light_choice.h"

namespace bounce {

// The largest image or window side, pixels (a 16384² radiance image is 3 GiB).
inline constexpr int kMaxImageSide = 16384;

struct SharedOptions {
  std::string scene;               // scene file: .gltf, .glb, .obj, or a .json wrapper
  std::string camera;              // the scene's camera by name; empty: its first
  int width = 0, height = 0;       // the image or window, pixels (0: the tool's rule)
  float exposure = 0.0f;           // EV: a tone-mapped pixel shows radiance × 2^EV
  std::string bake;                // bake folder; empty: found for the scene (bake_search.h)
  bool noBake = false;             // draw without baked light
  std::string mode;                // a render mode's name; empty: full with a bake, direct without
  int msaa = 4;                    // samples per pixel of the raster; 1: no anti-aliasing
  std::string costCount = "vpls";  // the cost view's count: lights, vpls or taps
  std::optional<float> costMax;    // the count at the red end of its scale; none: the tool's rule
  std::string dynamicVpls = "retrace";  // VPLs with dynamic instances: retrace or cut
  int maxDepth = 64;                    // most diffuse reflections along a path
  uint32_t seed = 0;                    // sampler seed
  int threads = 0;                      // worker threads; 0: all cores
  std::string backend = "embree";       // ray kernel: embree or bvh
  std::string lightChoice = lightChoiceName(LightChoice{});  // place or power (light_choice.h)
};

// `scene`, required.
void addSceneOption(CLI::App& app, SharedOptions& o);
// --camera NAME.
void addCameraOption(CLI::App& app, SharedOptions& o);
// --width, --height in pixels, each in [minSide, 16384]; `what` names them ("image",
// "window"), `defaults` says the tool's default ("default 512", ...).
void addSizeOptions(CLI::App& app, SharedOptions& o, int minSide, const std::string& what,
                    const std::string& defaults);
// --exposure EV.
void addExposureOption(CLI::App& app, SharedOptions& o);
// --bake DIR and --no-bake, which exclude each other.
void addBakeOptions(CLI::App& app, SharedOptions& o);
// --mode NAME, one of `modes` (render/render_mode.h's renderModeNames()); `lead` opens its
// help ("what to draw", "start in this mode").
void addModeOption(CLI::App& app, SharedOptions& o, const std::vector<std::string>& modes,
                   const std::string& lead);
// --msaa N in [1, 64].
void addMsaaOption(CLI::App& app, SharedOptions& o);
// --cost-count and --cost-max for the cost view; `scaleDefault` says how the tool picks the
// scale's end when --cost-max is not given.
void addCostViewOptions(CLI::App& app, SharedOptions& o, const std::string& scaleDefault);
// --dynamic-vpls retrace|cut.
void addDynamicVplsOption(CLI::App& app, SharedOptions& o);
// The path tracer's --max-depth, --seed, --threads, --backend, --light-choice.
void addPathTracingOptions(CLI::App& app, SharedOptions& o);

}  // namespace bounce
