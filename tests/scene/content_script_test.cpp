// The committed scenes are exactly what their scripts generate (content/README.md): rerunning
// each script into a temporary file must reproduce the committed file byte for byte.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "gltf_fixture.h"

namespace bounce {
namespace {

void expectRegenerates(const std::string& script, const std::string& committed) {
  const std::filesystem::path python = "/usr/bin/python3";  // Debian's, standard library only
  if (!std::filesystem::exists(python)) GTEST_SKIP() << "no " << python;
  test::TempDir dir;
  const std::filesystem::path out = dir / "regenerated.gltf";
  const std::string command =
      python.string() + " " + BOUNCE_SOURCE_DIR "/content/" + script + " " + out.string();
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const std::vector<unsigned char> fresh = test::readAll(out);
  const std::vector<unsigned char> stored =
      test::readAll(BOUNCE_SOURCE_DIR "/content/" + committed);
  ASSERT_FALSE(stored.empty());
  EXPECT_TRUE(fresh == stored) << committed << " differs from what " << script
                               << " generates: rerun the script and commit its output";
}

TEST(ContentScripts, CornellBoxIsReproducible) {
  expectRegenerates("cornell_box/make_cornell_box.py", "cornell_box/cornell_box.gltf");
}

TEST(ContentScripts, CornellBoxDynamicIsReproducible) {
  expectRegenerates("cornell_box_dynamic/make_cornell_box_dynamic.py",
                    "cornell_box_dynamic/cornell_box_dynamic.gltf");
}

TEST(ContentScripts, VplCornerIsReproducible) {
  expectRegenerates("vpl_corner/make_vpl_corner.py", "vpl_corner/vpl_corner.gltf");
}

TEST(ContentScripts, PointOverPlaneIsReproducible) {
  expectRegenerates("point_over_plane/make_point_over_plane.py",
                    "point_over_plane/point_over_plane.gltf");
}

TEST(ContentScripts, AtriumIsReproducible) {
  expectRegenerates("atrium/make_atrium.py", "atrium/atrium.gltf");
}

}  // namespace
}  // namespace bounce
