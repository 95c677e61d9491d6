// bounce-view's --script files (cli/viewer_script.h): every command read with its arguments and
// line; every mistake refused naming the file, the line and the reason.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli/viewer_script.h"
#include "io/load_error.h"

namespace bounce {
namespace {

namespace fs = std::filesystem;
const std::vector<std::string> kModes = {"full", "direct", "indirect"};

fs::path writeScript(const std::string& name, const std::string& text) {
  const fs::path file = fs::temp_directory_path() / ("bounce_viewer_script_" + name + ".txt");
  std::ofstream(file) << text;
  return file;
}

std::string refusal(const std::string& text) {
  const fs::path file = writeScript("bad", text);
  try {
    readViewerScript(file, kModes);
  } catch (const LoadError& e) {
    EXPECT_EQ(e.file(), file);
    return e.reason();
  }
  return "";
}

TEST(ViewerScript, ReadsEveryCommandWithItsLine) {
  const fs::path file = writeScript("all",
                                    "# a session\n"
                                    "camera corner\n"
                                    "view 1 2 3  0 0.5 -1\n"
                                    "\n"
                                    "mode indirect   # baked light only\n"
                                    "exposure -1.5\n"
                                    "panel off\n"
                                    "frames 3\n"
                                    "capture out/a.exr\n"
                                    "window out/w.png\n"
                                    "light lamp position 0 2.5 -1\n");
  const std::vector<ScriptCommand> c = readViewerScript(file, kModes);
  using Kind = ScriptCommand::Kind;
  ASSERT_EQ(c.size(), 9u);
  EXPECT_EQ(c[8].kind, Kind::Light);
  EXPECT_EQ(c[8].text, "lamp");
  EXPECT_EQ(c[8].field, "position");
  EXPECT_EQ(c[8].value, glm::vec3(0, 2.5f, -1));
  EXPECT_EQ(c[0].kind, Kind::Camera);
  EXPECT_EQ(c[0].text, "corner");
  EXPECT_EQ(c[0].line, 2);
  EXPECT_EQ(c[1].kind, Kind::View);
  EXPECT_EQ(c[1].position, glm::vec3(1, 2, 3));
  EXPECT_EQ(c[1].target, glm::vec3(0, 0.5f, -1));
  EXPECT_EQ(c[2].kind, Kind::Mode);
  EXPECT_EQ(c[2].text, "indirect");
  EXPECT_EQ(c[2].line, 5);
  EXPECT_EQ(c[3].number, -1.5f);
  EXPECT_EQ(c[4].kind, Kind::Panel);
  EXPECT_FALSE(c[4].on);
  EXPECT_EQ(c[5].count, 3);
  EXPECT_EQ(c[6].kind, Kind::Capture);
  EXPECT_EQ(c[6].text, "out/a.exr");
  EXPECT_EQ(c[7].kind, Kind::Window);
}

TEST(ViewerScript, ReadsBookmarksAndVplControls) {
  const fs::path file =
      writeScript("bookmarks", "bookmark save 2\nbookmark go 4\nvpl-paths 200\nvpl-clamp 0.03\n");
  const std::vector<ScriptCommand> c = readViewerScript(file, kModes);
  using Kind = ScriptCommand::Kind;
  ASSERT_EQ(c.size(), 4u);
  EXPECT_EQ(c[0].kind, Kind::BookmarkSave);
  EXPECT_EQ(c[0].count, 2);
  EXPECT_EQ(c[1].kind, Kind::BookmarkGo);
  EXPECT_EQ(c[1].count, 4);
  EXPECT_EQ(c[2].kind, Kind::VplPaths);
  EXPECT_EQ(c[2].count, 200);
  EXPECT_EQ(c[3].kind, Kind::VplClamp);
  EXPECT_EQ(c[3].number, 0.03f);
}

TEST(ViewerScript, MistakesNameTheLineAndTheReason) {
  EXPECT_EQ(refusal("frames 1\nzoom 2\n"),
            "line 2: unknown command 'zoom' (camera, view, mode, exposure, panel, frames, "
            "capture, window, light, rebake, wait-bake, cancel-bake, bookmark, vpl-paths, "
            "vpl-clamp, reference, compare)");
  EXPECT_EQ(refusal("reference ref.png\n"), "line 1: ref.png: a reference is an EXR file (.exr)");
  EXPECT_EQ(refusal("compare side\n"),
            "line 1: 'compare' takes off, split or difference, not 'side'");
  EXPECT_EQ(refusal("bookmark keep 1\n"), "line 1: 'bookmark' takes save or go, not 'keep'");
  EXPECT_EQ(refusal("bookmark go 5\n"), "line 1: bookmark 5 is not a whole number in [1, 4]");
  EXPECT_EQ(refusal("bookmark save 0\n"), "line 1: bookmark 0 is not a whole number in [1, 4]");
  EXPECT_EQ(refusal("vpl-paths 0\n"),
            "line 1: light path count 0 is not a whole number in [1, 1e9]");
  EXPECT_EQ(refusal("vpl-clamp -0.1\n"), "line 1: a clamp distance is not negative");
  EXPECT_EQ(refusal("light sun colour 1 1 1\n"),
            "line 1: 'light' sets intensity, position or direction, not 'colour'");
  EXPECT_EQ(refusal("light sun intensity 1 -1 1\n"), "line 1: a light's intensity is not negative");
  EXPECT_EQ(refusal("rebake now\n"), "line 1: 'rebake' takes 0 arguments, not 1");
  EXPECT_EQ(refusal("view 1 2 3\n"), "line 1: 'view' takes 6 arguments, not 3");
  EXPECT_EQ(refusal("exposure bright\n"), "line 1: exposure 'bright' is not a finite number");
  EXPECT_EQ(refusal("exposure 1e999\n"), "line 1: exposure '1e999' is not a finite number");
  EXPECT_EQ(refusal("mode sepia\n"), "line 1: no render mode 'sepia'");
  EXPECT_EQ(refusal("capture a.jpg\n"), "line 1: a.jpg: the file must end in .png or .exr");
  EXPECT_EQ(refusal("frames 0\n"), "line 1: frame count 0 is not a whole number in [1, 100000]");
  EXPECT_EQ(refusal("frames 2.5\n"),
            "line 1: frame count 2.5 is not a whole number in [1, 100000]");
  EXPECT_EQ(refusal("panel maybe\n"), "line 1: 'panel' takes on or off, not 'maybe'");
  EXPECT_EQ(refusal("view 1 1 1 1 1 1\n"), "line 1: 'view' looks from a point at itself");
  EXPECT_EQ(refusal("# nothing\n\n"), "the script has no commands");
}

}  // namespace
}  // namespace bounce
