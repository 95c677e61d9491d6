// bounce-view's --script replay (cli/viewer_script_replay.h) against a viewer that records what
// it is asked: the commands that set state run before a frame is drawn, captures after it;
// `frames N` takes N frames and what follows it starts with the next frame; wait-bake holds the
// script while a re-bake is pending; a command the viewer refuses is reported as
// "FILE: line N: reason".
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/viewer_script.h"
#include "cli/viewer_script_replay.h"

namespace bounce {
namespace {

namespace fs = std::filesystem;

// Records each call as one word (and its argument); `pendingFrames` frames of re-bake pending.
class RecordingViewer final : public ScriptActions {
 public:
  std::vector<std::string> calls;
  int pendingFrames = 0;
  std::string refuseCamera;  // selectCamera throws for this name

  void selectCamera(const std::string& name) override {
    if (name == refuseCamera) throw std::runtime_error("no camera '" + name + "'");
    calls.push_back("camera " + name);
  }
  void lookFrom(const glm::vec3&, const glm::vec3&) override { calls.push_back("view"); }
  void setModeNamed(const std::string& mode) override { calls.push_back("mode " + mode); }
  void setExposure(float ev) override { calls.push_back("exposure " + std::to_string(ev)); }
  void showPanel(bool on) override { calls.push_back(on ? "panel on" : "panel off"); }
  void startRebake() override { calls.push_back("rebake"); }
  void cancelRebake() override { calls.push_back("cancel-bake"); }
  void setLightField(const std::string& light, const std::string& field,
                     const glm::vec3&) override {
    calls.push_back("light " + light + " " + field);
  }
  void saveBookmark(std::size_t slot) override {
    calls.push_back("bookmark save " + std::to_string(slot));
  }
  void goToBookmark(std::size_t slot) override {
    calls.push_back("bookmark go " + std::to_string(slot));
  }
  void setVplPaths(uint64_t paths) override {
    calls.push_back("vpl-paths " + std::to_string(paths));
  }
  void setVplClamp(float) override { calls.push_back("vpl-clamp"); }
  void loadReference(const std::string& file) override { calls.push_back("reference " + file); }
  void setComparison(const std::string& how) override { calls.push_back("compare " + how); }
  void capture(const std::string& file) override { calls.push_back("capture " + file); }
  void captureWindow(const std::string& file) override { calls.push_back("window " + file); }
  bool rebakePending() override { return pendingFrames-- > 0; }
};

ScriptReplay replayOf(const std::string& name, const std::string& text) {
  const fs::path file = fs::temp_directory_path() / ("bounce_replay_" + name + ".txt");
  std::ofstream(file) << text;
  return ScriptReplay(file.string(), readViewerScript(file, {"full", "direct"}));
}

// One frame as the viewer draws it: the state commands, the frame (recorded), the captures.
bool frame(ScriptReplay& replay, RecordingViewer& viewer) {
  replay.beforeFrame(viewer);
  viewer.calls.push_back("draw");
  return replay.afterFrame(viewer);
}

TEST(ViewerScriptReplay, StateBeforeTheFrameCapturesAfterItFramesCountFrames) {
  ScriptReplay replay = replayOf("order",
                                 "camera top\n"
                                 "mode direct\n"
                                 "capture a.png\n"
                                 "exposure 1\n"
                                 "frames 3\n"
                                 "window b.png\n"
                                 "bookmark save 2\n");
  RecordingViewer viewer;
  EXPECT_FALSE(frame(replay, viewer));  // camera, mode, draw, capture a.png
  EXPECT_FALSE(frame(replay, viewer));  // exposure, draw 1 of 3
  EXPECT_FALSE(frame(replay, viewer));  // draw 2 of 3
  EXPECT_FALSE(frame(replay, viewer));  // draw 3 of 3: `frames 3` is done
  EXPECT_FALSE(frame(replay, viewer));  // the next frame, then the window capture
  EXPECT_TRUE(frame(replay, viewer));   // bookmark, draw: the script has ended
  EXPECT_EQ(viewer.calls,
            (std::vector<std::string>{"camera top", "mode direct", "draw", "capture a.png",
                                      "exposure 1.000000", "draw", "draw", "draw", "draw",
                                      "window b.png", "bookmark save 1", "draw"}));
}

// wait-bake: frames go on (drawing the re-bake's passes) until nothing is pending, and the
// capture after it sees the frame drawn then.
TEST(ViewerScriptReplay, WaitBakeHoldsTheScriptWhileARebakeIsPending) {
  ScriptReplay replay = replayOf("wait", "rebake\nwait-bake\ncapture c.exr\n");
  RecordingViewer viewer;
  viewer.pendingFrames = 2;
  EXPECT_FALSE(frame(replay, viewer));
  EXPECT_FALSE(frame(replay, viewer));
  EXPECT_TRUE(frame(replay, viewer));
  EXPECT_EQ(viewer.calls,
            (std::vector<std::string>{"rebake", "draw", "draw", "draw", "capture c.exr"}));
}

TEST(ViewerScriptReplay, ARefusedCommandNamesTheFileAndTheLine) {
  ScriptReplay replay = replayOf("refused", "mode full\n\ncamera nowhere\n");
  RecordingViewer viewer;
  viewer.refuseCamera = "nowhere";
  try {
    replay.beforeFrame(viewer);
    FAIL() << "the refused camera was accepted";
  } catch (const std::runtime_error& e) {
    const std::string file = (fs::temp_directory_path() / "bounce_replay_refused.txt").string();
    EXPECT_EQ(std::string(e.what()), file + ": line 3: no camera 'nowhere'");
  }
}

}  // namespace
}  // namespace bounce
