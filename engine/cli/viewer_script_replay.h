// bounce-view's `--script FILE` replayed frame by frame (cli/viewer_script.h parses it): the
// commands that set state run before a frame is drawn, captures, frame counts and wait-bake
// after it. The viewer is reached through ScriptActions only, so the replay's order and its
// error messages ("FILE: line N: why") live here and the viewer's state stays in the viewer.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "cli/viewer_script.h"

namespace bounce {

// What a script can ask of the viewer; each call throws std::exception with the reason when it
// cannot be done (the replay adds the file and the line).
class ScriptActions {
 public:
  virtual void selectCamera(const std::string& name) = 0;
  virtual void lookFrom(const glm::vec3& position, const glm::vec3& target) = 0;  // m
  virtual void setModeNamed(const std::string& mode) = 0;
  virtual void setExposure(float ev) = 0;
  virtual void showPanel(bool on) = 0;
  virtual void startRebake() = 0;
  virtual void cancelRebake() = 0;
  // `field` intensity (W/sr; a directional light's irradiance W/m²), position (m) or direction.
  virtual void setLightField(const std::string& light, const std::string& field,
                             const glm::vec3& value) = 0;
  virtual void saveBookmark(std::size_t slot) = 0;  // 0-based
  virtual void goToBookmark(std::size_t slot) = 0;
  virtual void setVplPaths(uint64_t paths) = 0;
  virtual void setVplClamp(float distance) = 0;  // m
  virtual void loadReference(const std::string& file) = 0;
  virtual void setComparison(const std::string& how) = 0;   // off, split or difference
  virtual void capture(const std::string& file) = 0;        // the scene's frame
  virtual void captureWindow(const std::string& file) = 0;  // the window as shown
  // wait-bake: whether a re-bake still runs or has a pass not yet drawn.
  virtual bool rebakePending() = 0;

 protected:
  ~ScriptActions() = default;
};

class ScriptReplay {
 public:
  ScriptReplay(std::string file, std::vector<ScriptCommand> commands);

  bool empty() const { return commands_.empty(); }
  // The commands that set state, up to the next capture, frame count or wait-bake.
  void beforeFrame(ScriptActions& viewer);
  // The captures, frame counts and waits after a frame; whether the script has ended.
  bool afterFrame(ScriptActions& viewer);

 private:
  void run(const ScriptCommand& c, ScriptActions& viewer);

  std::string file_;
  std::vector<ScriptCommand> commands_;
  std::size_t next_ = 0;  // the next command
  int framesDrawn_ = 0;   // frames drawn of the current `frames N`
};

}  // namespace bounce
