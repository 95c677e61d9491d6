// bounce-trace end to end: loader, units, camera convention, files and exit codes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <glm/gtc/matrix_transform.hpp>

#include "image/image_io.h"
#include "scene/load.h"
#include "support/tool_run.h"
#include "trace/camera_render.h"

namespace bounce {
namespace {

namespace fs = std::filesystem;

const std::string kTool = std::string(BOUNCE_BIN_DIR) + "/bounce-trace";
const fs::path kContent = fs::path(BOUNCE_SOURCE_DIR) / "content";

fs::path scratchDir() {
  return fs::temp_directory_path() / ("bounce_trace_app_test_" + std::to_string(::getpid()));
}

fs::path scratch(const std::string& name) {
  fs::create_directories(scratchDir());
  return scratchDir() / name;
}

// Removes the scratch folder after all tests.
class ScratchCleanup : public ::testing::Environment {
 public:
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(scratchDir(), ec);
  }
};
const auto* const kCleanup = ::testing::AddGlobalTestEnvironment(new ScratchCleanup);

using test::readText;

int run(const std::string& arguments) {
  return test::exitCode(std::system((kTool + " " + arguments + " 2>/dev/null").c_str()));
}

// point_over_plane.gltf: ρ = 0.5 plane, 1 W/sr point light 1 m above (content/README.md).
// A pixel's value estimates the mean of L = ρ/π · I·h/(h² + r²)^{3/2} over its footprint on
// the plane (box filter). The expected value and the variance of L over the footprint come
// from a 32×32 grid of film positions; one jittered sample has that variance, so the SE of
// a 64-sample pixel is σ/8 and the tolerance 5 SE (plus float rounding).
TEST(TraceApp, PointOverPlaneMatchesTheInverseSquareLaw) {
  const fs::path scene = kContent / "point_over_plane" / "point_over_plane.gltf";
  const fs::path out = scratch("pop.exr");
  ASSERT_EQ(run(scene.string() + " --width 12 --height 12 --spp 64 --out " + out.string()), 0);
  const Image image = readExr(out);
  ASSERT_EQ(image.width, 12);
  const Scene loaded = loadScene(scene);
  ASSERT_EQ(loaded.lights.size(), 1u);
  const Light& light = loaded.lights[0];
  const double rho = loaded.materials.at(0).albedo.g;
  const double intensity = light.intensity.g;
  const double h = light.position.y;  // the plane is y = 0
  // The plane's extent in x and z: a ray that misses it (above the horizon or past its edge)
  // sees black.
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const glm::vec3& p : loaded.meshes.at(0).positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  for (int y = 0; y < 12; ++y) {
    for (int x = 0; x < 12; ++x) {
      double sum = 0.0, sum2 = 0.0;
      const int grid = 32;
      for (int j = 0; j < grid; ++j) {
        for (int i = 0; i < grid; ++i) {
          const Ray ray =
              cameraRay(loaded.cameras[0], 12, 12, x + (i + 0.5f) / grid, y + (j + 0.5f) / grid);
          const double t = -static_cast<double>(ray.origin.y) / ray.direction.y;
          const double wx = ray.origin.x + t * ray.direction.x;
          const double wz = ray.origin.z + t * ray.direction.z;
          const bool onPlane = t > 0 && wx >= lo.x && wx <= hi.x && wz >= lo.z && wz <= hi.z;
          const double px = wx - light.position.x;
          const double pz = wz - light.position.z;
          const double l =
              onPlane ? rho / M_PI * intensity * h / std::pow(h * h + px * px + pz * pz, 1.5) : 0.0;
          sum += l;
          sum2 += l * l;
        }
      }
      const double n = grid * grid;
      const double mean = sum / n;
      const double sigma = std::sqrt(std::max(0.0, sum2 / n - mean * mean));
      EXPECT_NEAR(image.at(x, y).g, mean, 5.0 * sigma / 8.0 + 1e-5 * mean) << x << "," << y;
    }
  }
}

// cameraRay against the pinhole model written out independently: a point at camera-space
// (X, Y, Z), Z < 0, projects to film position
//   x = w/2 · (1 + X / (−Z · tan(yfov/2) · aspect)),  y = h/2 · (1 − Y / (−Z · tan(yfov/2))),
// aspect = w/h (origin top-left, y down). The ray through that film position must pass
// through the point's world position, for non-square images (both orientations), a rotated
// and translated camera, and points near the film's corners (where a wrong field of view or
// aspect moves the ray furthest). Tolerance: float rounding, 1e-5 of the distance.
TEST(TraceApp, CameraRayFollowsThePinholeProjection) {
  Camera camera;
  camera.yfov = 0.9f;
  const glm::mat4 rotation =
      glm::rotate(glm::mat4(1.0f), 0.7f, glm::normalize(glm::vec3(0.3f, 1.0f, -0.4f)));
  camera.cameraToWorld = glm::translate(glm::mat4(1.0f), glm::vec3(1.5f, -2.0f, 0.7f)) * rotation;
  const double tanHalf = std::tan(0.5 * static_cast<double>(camera.yfov));
  for (const glm::ivec2 size : {glm::ivec2(48, 20), glm::ivec2(20, 48), glm::ivec2(33, 33)}) {
    const double aspect = static_cast<double>(size.x) / size.y;
    int onFilm = 0;
    for (const glm::dvec3 c : {glm::dvec3(0.9, 0.35, -2.0), glm::dvec3(-2.1, -1.1, -5.0),
                               glm::dvec3(0.35, 0.85, -2.0), glm::dvec3(-0.38, -0.85, -2.0),
                               glm::dvec3(0.3, -0.1, -1.0), glm::dvec3(0.1, -0.3, -1.0)}) {
      const double x = size.x / 2.0 * (1.0 + c.x / (-c.z * tanHalf * aspect));
      const double y = size.y / 2.0 * (1.0 - c.y / (-c.z * tanHalf));
      if (x < 0 || x > size.x || y < 0 || y > size.y) continue;  // off the film
      ++onFilm;
      const glm::dvec3 world = glm::dvec3(camera.cameraToWorld * glm::vec4(glm::vec3(c), 1.0f));
      const Ray ray =
          cameraRay(camera, size.x, size.y, static_cast<float>(x), static_cast<float>(y));
      const glm::dvec3 toPoint = world - glm::dvec3(ray.origin);
      const glm::dvec3 dir = glm::normalize(glm::dvec3(ray.direction));
      const double along = glm::dot(toPoint, dir);
      const double miss = glm::length(toPoint - along * dir);  // distance of the point to the ray
      EXPECT_GT(along, 0.0);
      EXPECT_LT(miss, 1e-5 * glm::length(toPoint))
          << size.x << "x" << size.y << " point " << c.x << "," << c.y << "," << c.z << " at film "
          << x << "," << y;
    }
    EXPECT_GE(onFilm, 3) << size.x << "x" << size.y;
  }
}

// The Cornell box seen from its camera has the red wall on the left, the green on the right
// (content/README.md): a check of the camera convention (−Z forward, +Y up, x to the right).
TEST(TraceApp, CornellBoxRedWallOnTheLeft) {
  const fs::path out = scratch("cornell.exr");
  const fs::path png = scratch("cornell.png");
  ASSERT_EQ(run((kContent / "cornell_box" / "cornell_box.gltf").string() +
                " --width 16 --height 16 --spp 8 --out " + out.string() + " --png " + png.string()),
            0);
  EXPECT_TRUE(fs::exists(png));
  const Image image = readExr(out);
  ASSERT_TRUE(image.allFinite());
  glm::dvec3 left(0.0), right(0.0);
  for (int y = 4; y < 12; ++y) {
    left += glm::dvec3(image.at(1, y));
    right += glm::dvec3(image.at(14, y));
  }
  EXPECT_GT(left.r, 2.0 * left.g);
  EXPECT_GT(right.g, 2.0 * right.r);
}

// OBJ files bring no camera: bounce-trace frames the scene's bounds (scene/framing.h) as
// bounce-render does. McGuire's box is open towards +Z, so the framed camera (on the +Z side,
// looking down −Z) sees the lit interior: the image is finite and not black.
TEST(TraceApp, SceneWithoutCameraIsFramed) {
  const fs::path obj =
      fs::path(BOUNCE_SHARED_SCENES) / "mcguire_cornell_box" / "CornellBox-Original.obj";
  if (!fs::exists(obj)) GTEST_SKIP() << obj << " not found";
  const fs::path out = scratch("framed.exr");
  ASSERT_EQ(run(obj.string() + " --width 8 --height 8 --spp 4 --out " + out.string()), 0);
  const Image image = readExr(out);
  ASSERT_TRUE(image.allFinite());
  double sum = 0.0;
  for (const glm::vec3& p : image.pixels) sum += p.r + p.g + p.b;
  EXPECT_GT(sum, 0.0);
}

// A camera with aspect ratio 10⁶ and only --height given: the derived width (10⁶ px) is
// clamped to 16384 and stderr says so, naming the camera and its aspect.
TEST(TraceApp, ExtremeCameraAspectIsClamped) {
  const fs::path source = kContent / "point_over_plane" / "point_over_plane.gltf";
  std::string text = readText(source);
  const std::string key = "\"aspectRatio\": 1.0";
  const std::size_t at = text.find(key);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, key.size(), "\"aspectRatio\": 1000000.0");
  const fs::path scene = scratch("wide.gltf");
  { std::ofstream(scene) << text; }
  const fs::path out = scratch("wide.exr");
  const fs::path log = scratch("wide.log");
  const std::string command = kTool + " " + scene.string() + " --height 1 --spp 1 --quiet --out " +
                              out.string() + " 2>" + log.string();
  ASSERT_EQ(test::exitCode(std::system(command.c_str())), 0);
  EXPECT_EQ(readExr(out).width, 16384);
  const std::string messages = readText(log);
  EXPECT_NE(messages.find("camera 'top' has aspect ratio 1e+06"), std::string::npos) << messages;
  EXPECT_NE(messages.find("16384x1"), std::string::npos) << messages;
  EXPECT_NE(messages.find(", 0 non-finite samples"), std::string::npos) << messages;
}

TEST(TraceApp, BadInputFailsWithNonZeroExit) {
  const fs::path out = scratch("bad.exr");
  EXPECT_NE(run("/nonexistent/scene.gltf --out " + out.string()), 0);
  const std::string cornell = (kContent / "cornell_box" / "cornell_box.gltf").string();
  EXPECT_NE(run(cornell + " --backend nope --out " + out.string()), 0);
  EXPECT_NE(run(cornell + " --camera nope --width 4 --height 4 --out " + out.string()), 0);
  // An output path below a regular file cannot be written.
  const fs::path file = scratch("a_file");
  { std::ofstream(file) << "x"; }
  EXPECT_NE(run(cornell + " --width 4 --height 4 --out " + (file / "x.exr").string()), 0);
  EXPECT_NE(run(cornell), 0);  // --out missing
  EXPECT_FALSE(fs::exists(out));
}

// Each output's extension says its format: `--out x.png` wrote EXR data under a .png name; now
// it is refused before tracing. And outputs are all or nothing: a --png that cannot be written
// leaves no --out EXR behind (the exit status 1 used to come with the EXR in place).
TEST(TraceApp, OutputsMatchTheirExtensionAndAreAllOrNothing) {
  const std::string cornell = (kContent / "cornell_box" / "cornell_box.gltf").string();
  const fs::path png = scratch("wrong.png");
  const std::string log = scratch("wrong.log").string();
  const std::string command =
      kTool + " " + cornell + " --width 4 --height 4 --spp 1 --out " + png.string() + " 2> " + log;
  EXPECT_NE(std::system(command.c_str()), 0);
  EXPECT_FALSE(fs::exists(png));
  EXPECT_NE(readText(log).find("wrong.png: the file must end in .exr"), std::string::npos)
      << readText(log);

  const fs::path exr = scratch("first.exr");
  fs::create_directories(scratch("taken.png"));
  EXPECT_EQ(run(cornell + " --width 4 --height 4 --spp 1 --quiet --out " + exr.string() +
                " --png " + scratch("taken.png").string()),
            1);
  EXPECT_FALSE(fs::exists(exr));
}

}  // namespace
}  // namespace bounce
