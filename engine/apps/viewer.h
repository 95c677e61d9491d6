// bounce-view: the scene in a window (GLFW, OpenGL 3.3 core) with a fly camera, the forward
// renderer and, with a bake (--bake, or the one found for the scene as bounce-render finds it,
// bake_folder/bake_search.h), its baked light. Its rooms:
//   viewer_input.h              the keys and the mouse (the controls are listed there)
//   viewer_panel.h              the panel (H): the bake's facts, modes, exposure, cameras and
//                               bookmarks, the VPLs' light paths and clamp, objects, lights, times
//   cli/viewer_script_replay.h  --script FILE, replayed frame by frame (GL-free, tested alone)
//   viewer_rebake.h             the background re-bake (the panel's button, the script's rebake)
// M cycles the modes the bake allows (without a bake direct, cascades and cost), C toggles the
// chart view; dynamic objects (extras.bounce.mobility = "dynamic") move along the world axes
// nearest the camera's right, forward and up at a quarter of the scene's diagonal per second.
// The title shows the camera, the mode, the frame time, the speed, the exposure and the selected
// object with its position. `--frames N --screenshot FILE` renders N frames, saves the last one
// and exits (for tests).
#pragma once

#include <string>
#include <vector>

#include "cli/shared_options.h"
#include "cli/viewer_script.h"
#include "scene/scene.h"

namespace bounce {

struct ViewerOptions {
  SharedOptions shared;  // scene, camera, window size, exposure, bake, mode, msaa, cost view
  int frames = 0;        // 0 = until closed
  std::string screenshot;
  std::string windowShot;  // the window as shown (panel included), EXR of display values
  std::string scriptFile;
  std::vector<ScriptCommand> script;  // read before the window opens
  bool noPanel = false;               // start with the panel hidden
  std::vector<std::string> moves;     // NAME X Y Z, repeated
  std::string reference;              // a reference EXR (bounce-trace) to compare the frame with
  std::string compare = "split";      // how, with --reference (render/reference_view.h)
};

// Finds the bake (--bake, else the scene's, unless --no-bake), opens the window and draws until
// it is closed, --frames have been drawn or the script has ended; returns the exit code. Throws
// for a bake that cannot be read or a mode that needs one.
int runViewer(const ViewerOptions& options, Scene scene);

}  // namespace bounce
