// bounce-view's command line (viewer.h is the viewer): the options it shares with bounce-render
// (cli/shared_options.h), its captures, script and reference; the scene loaded with --move.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "cli/instance_move_option.h"
#include "cli/shared_options.h"
#include "cli/viewer_script.h"
#include "render/render_mode.h"
#include "scene/instance_move.h"
#include "scene/load.h"
#include "viewer.h"

namespace {

// --frames, --screenshot, --window-shot and --script: what is drawn before the viewer exits and
// what it saves.
void addCaptureOptions(CLI::App& app, bounce::ViewerOptions& options) {
  app.add_option("--frames", options.frames, "render this many frames, then exit")
      ->check(CLI::PositiveNumber);
  // Captures are written by extension: .png (tone-mapped or display values) or .exr.
  const CLI::Validator kImageFile(
      [](const std::string& path) -> std::string {
        const auto ext = std::filesystem::path(path).extension();
        return ext == ".png" || ext == ".exr" ? "" : path + ": the file must end in .png or .exr";
      },
      "FILE.png|FILE.exr");
  app.add_option("--screenshot", options.screenshot,
                 "with --frames: save the last frame here (.png tone-mapped or .exr linear)")
      ->needs("--frames")
      ->check(kImageFile);
  app.add_option("--window-shot", options.windowShot,
                 "with --frames: save the window as shown, panel included (.png, or .exr of the "
                 "display values in [0, 1], sRGB-encoded; --screenshot holds the scene's frame "
                 "only)")
      ->needs("--frames")
      ->check(kImageFile);
  app.add_option("--script", options.scriptFile,
                 "replay a session: camera, view, mode, exposure, panel, frames, capture, window, "
                 "light, rebake, wait-bake, cancel-bake, bookmark, vpl-paths and vpl-clamp "
                 "commands, one per line (engine/cli/viewer_script.h); exits after the last")
      ->check(CLI::ExistingFile);
}

// --reference and --compare: a reference EXR beside the frame.
void addReferenceOptions(CLI::App& app, bounce::ViewerOptions& options) {
  app.add_option("--reference", options.reference,
                 "a reference EXR of the same camera (bounce-trace --out FILE.exr at the window's "
                 "size) shown beside the frame, both through the same exposure and tone mapper")
      ->check(CLI::ExistingFile);
  app.add_option("--compare", options.compare,
                 "with --reference: split (left the frame, right the reference; default) or "
                 "difference (the luminance relative difference: red brighter, blue darker, full "
                 "at 50%)")
      ->check(CLI::IsMember({"split", "difference"}))
      ->needs("--reference");
}

// The script read, and its cameras checked, before a window opens.
void readScript(bounce::ViewerOptions& options, const bounce::Scene& scene) {
  if (options.scriptFile.empty()) return;
  options.script = bounce::readViewerScript(options.scriptFile, bounce::renderModeNames());
  for (const bounce::ScriptCommand& c : options.script)
    if (c.kind == bounce::ScriptCommand::Kind::Camera) try {
        (void)scene.findCamera(c.text);
      } catch (const std::exception& e) {
        throw std::runtime_error(options.scriptFile + ": line " + std::to_string(c.line) + ": " +
                                 e.what());
      }
}

}  // namespace

int main(int argc, char** argv) {
  bounce::ViewerOptions options;
  CLI::App app{
      "View a scene with the forward renderer in a window (OpenGL 3.3 core).\n"
      "W/A/S/D move, Q/E down/up, Shift faster, drag the mouse to look, +/- or the "
      "wheel change speed, Tab or 1-9 pick a camera, F12 saves PNG + EXR, [ and ] change the "
      "exposure, Esc quits. M cycles the modes (without a bake direct and cascades), C toggles the "
      "chart view. Dynamic "
      "objects: G selects the next, J/L, I/K, U/O move it left/right, away/towards, down/up. "
      "F1-F4 go to a camera bookmark, Shift+F1-F4 save one. H shows or hides the panel.",
      "bounce-view"};
  bounce::SharedOptions& shared = options.shared;
  shared.width = 1280;
  shared.height = 720;
  bounce::addSceneOption(app, shared);
  bounce::addCameraOption(app, shared);
  bounce::addSizeOptions(app, shared, 16, "window", "default 1280x720");
  bounce::addExposureOption(app, shared);
  addCaptureOptions(app, options);
  bounce::addBakeOptions(app, shared);
  bounce::addMsaaOption(app, shared);
  app.add_flag("--no-panel", options.noPanel, "start with the panel hidden (H shows it)");
  addReferenceOptions(app, options);
  bounce::addModeOption(app, shared, bounce::renderModeNames(), "start in this mode");
  bounce::addCostViewOptions(app, shared,
                             "1, 2 or 5 x 10^k at or above the lights in the scene, the largest "
                             "VPL lightcut, or 64 taps");
  bounce::addDynamicVplsOption(app, shared);
  bounce::addMoveOption(app, options.moves);
  CLI11_PARSE(app, argc, argv);
  try {
    bounce::Scene scene = bounce::loadScene(options.shared.scene);
    readScript(options, scene);
    bounce::moveInstances(scene, bounce::parseInstanceMoves(options.moves));
    return bounce::runViewer(options, std::move(scene));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bounce-view: error: %s\n", e.what());
    return 1;
  }
}
