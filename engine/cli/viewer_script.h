// bounce-view's `--script FILE`: a session replayed frame by frame, for tests and for the
// README's pictures. One command per line, `#` starts a comment:
//   camera NAME          jump to the scene's camera NAME
//   view X Y Z TX TY TZ  stand at (X, Y, Z) m looking at (TX, TY, TZ) m (the current lens)
//   mode NAME            a render mode (one of `modes`: render/render_mode.h's names)
//   exposure EV          exposure in EV
//   panel on|off         show or hide the panel
//   frames N             draw N frames (N >= 1)
//   capture FILE         save the scene's frame (.png tone-mapped or .exr radiance)
//   window FILE          save the window as shown, panel included (.png, or .exr display values)
//   light NAME intensity R G B   set a point or spot light's intensity, W/sr (a directional
//                        light's irradiance, W/m²); `position X Y Z` (m), `direction X Y Z`
//   rebake               start a background re-bake (preview, then final, as the panel's button)
//   wait-bake            draw frames until the re-bake has finished and its last pass is drawn
//   cancel-bake          cancel the running re-bake
//   bookmark save|go N   save the current camera as bookmark N (1..kScriptBookmarks), or
//                        return to it (as Shift+F1..F4 and F1..F4)
//   vpl-paths N          draw the VPLs of the bake's first N light paths (N >= 1; the panel's
//                        "light paths")
//   vpl-clamp R          VPL clamp distance R m (>= 0; 0 unclamped)
//   reference FILE       load a reference EXR (bounce-trace's) and show it split with the frame
//   compare off|split|difference   how the frame is shown beside the reference
// Commands run in order, one per frame (a frames N takes N); the viewer exits after the last.
// Paths are as written (relative to the working folder). GL-free.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace bounce {

struct ScriptCommand {
  enum class Kind {
    Camera,
    View,
    Mode,
    Exposure,
    Panel,
    Frames,
    Capture,
    Window,
    Rebake,
    WaitBake,
    CancelBake,
    Light,
    BookmarkSave,
    BookmarkGo,
    VplPaths,
    VplClamp,
    Reference,
    Compare
  };
  Kind kind = Kind::Frames;
  int line = 0;      // 1-based, for messages
  std::string text;  // camera or mode name, file; compare: off, split or difference
  glm::vec3 position{0.0f}, target{0.0f};  // view
  float number = 0.0f;                     // exposure; vpl-clamp (m)
  std::string field;                       // light: intensity, position or direction
  glm::vec3 value{0.0f};                   // light: the field's new value
  int count = 1;                           // frames; the bookmark's slot (1-based); vpl-paths
  bool on = true;                          // panel
};

inline constexpr int kScriptBookmarks = 4;  // camera bookmarks: F1..F4

// Throws LoadError("FILE: line N: reason") for an unknown command, a wrong argument count, a
// number that does not parse or is not finite, a mode that does not exist, a capture whose
// extension is not .png or .exr, a frames count outside [1, 100000], or an empty script.
std::vector<ScriptCommand> readViewerScript(const std::filesystem::path& file,
                                            const std::vector<std::string>& modes);

}  // namespace bounce
