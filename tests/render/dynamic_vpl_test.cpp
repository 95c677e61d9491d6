// The VPL term on a dynamic object: the dynamic sphere of content/cornell_box_dynamic at three
// positions in the box, its indirect radiance from the renderer's VPLs against the path tracer,
// both through their command lines with the same --move, so the tools are shown to see one scene:
//
//   bounce-bake  cornell_box_dynamic.gltf -o B           (VPLs: bounce-bake's defaults)
//   bounce-render W.json --bake B --mode indirect --move sphere X Y Z --out r.exr
//   bounce-trace  W.json --indirect-only --move sphere X Y Z --spp S --std-error s.exr
//
// W.json wraps the scene with a camera at the Cornell camera's eye aimed at the sphere, its field
// of view fitted to the sphere, so that most of a small frame is sphere (the tracer's samples go
// where they are measured). Sphere pixels: the pixel's centre and four points near its corners
// all hit the sphere (camera rays against the moved scene with the baker's ray kernel, not the
// renderer under test), so the silhouette, where the rasterizer's centre sample and the tracer's
// box filter disagree, is left out.
//
// Error (as tests/render/indirect_accuracy.h, on 4×4-pixel blocks of sphere pixels, where the
// tracer's noise is 4× lower than per pixel): mean over the blocks of |Y_r − Y_t|/Y_t, Y the
// luminance. The tracer's own noise adds at most √(2/π)·mean(σ_b/Y_t) to it (σ_b the block's
// standard error from the per-pixel sample variances); asserted ≤ 3.5% at kSpp, a third of the
// 10% allowed, so the measure is the renderer's error. What the renderer's error is made of:
//   - VPL noise: N VPLs (the bake's count rule: cap 4096 or 1% relative error on the total flux;
//     4095 VPLs from ~1700 light paths here) are one random set: 3-11% on the sphere (measured
//     below with VPLs that know the sphere), a few % at 4N;
//   - clamp bias: VPLs closer than r = sqrt(A/(πN)) (bake.json's clampDistance, 1.2 cm here)
//     are capped, biasing low; the positions keep the sphere ≥ 2 cm from every surface: small;
//   - the sphere's own shadow: the bake leaves it out, so VPLs stand where the sphere shadows the
//     room (the floor or block under it); the tracer sees that shadow: +13..+39% here unless the
//     renderer dims those VPLs (first-bounce VPLs by the sphere's shadow from the light bring it
//     to 7..11%, VplErrorBudgetAgainstThePathTracer);
//   - visibility: blocks between a VPL and the sphere (VPL shadow maps approximate it): 2-8%;
//   - culling: VPLs left out or merged per tile (the renderer's lightcut) bias either way.
//
// Runtime (release): the suite's set-up traces 3 × 24² pixels × 2560 spp (~4 s CPU), the GL-free
// test ~2 s; the renderer test ~1 s more.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "bake_folder/bake_folder.h"
#include "image/image_io.h"
#include "image/luminance.h"
#include "ray/ray_kernel.h"
#include "scene/instance_move.h"
#include "scene/load.h"
#include "scene/static_scene.h"
#include "scene/world_geometry.h"
#include "trace/camera_render.h"
#include "trace/sampling.h"
#include "vpl/vpl_gather.h"
#include "vpl/vpl_generate.h"
#include "vpl_runtime/vpl_occlusion.h"

namespace bounce {
namespace {

namespace fs = std::filesystem;

constexpr int kSize = 24;  // pixels per side
constexpr int kBlock = 4;  // pixels per side of a compared block
// 4x bounce-bake's default: VPL noise on the sphere at the default N reaches 10.7% (mid-box,
// "traced with the sphere" row of docs/vpl_measurements.md); it falls as 1/sqrt(N), so 4N halves
// it.
constexpr int kBakeVpls = 16384;
constexpr int kSpp = 2560;       // tracer samples per pixel: its noise adds ≤ 3.5% (asserted)
constexpr float kRadius = 0.1f;  // the sphere's, m (make_cornell_box_dynamic.py)
const glm::vec3 kEye(0.278f, 0.273f, -0.8f);  // the Cornell camera (content/README.md)

struct Position {
  const char* what;
  glm::vec3 centre;  // m; ≥ 2 cm from every wall and block
};
const Position kPositions[] = {
    {"near the red wall", {0.42f, 0.30f, 0.12f}},    // 3.3 cm from it
    {"near the green wall", {0.14f, 0.30f, 0.30f}},  // 4 cm from it, 3.5 cm over the short block
    {"in the middle", {0.278f, 0.35f, 0.12f}},       // 8.5 cm over the short block
};

// Single-quoted for the shell; built with += (GCC 12 gives a false -Wrestrict on "'" + s).
std::string quote(const fs::path& p) {
  std::string quoted(1, '\'');
  quoted += p.string();
  quoted += '\'';
  return quoted;
}
std::string tool(const std::string& name) {
  return quote(fs::path(BOUNCE_BIN_DIR) / name);
}

// Runs `command`, returns its exit code and prints its output on failure.
int run(const std::string& command, const fs::path& log) {
  const int status = std::system((command + " > " + quote(log) + " 2>&1").c_str());
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (code != 0) {
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    ADD_FAILURE() << command << "\n" << text.str();
  }
  return code;
}

std::string moveFlag(const glm::vec3& p) {
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, " --move sphere %.9g %.9g %.9g", p.x, p.y, p.z);
  return buffer;
}

struct Comparison {
  std::size_t blocks = 0;                       // compared
  double error = 0.0;                           // mean |Y_r − Y_t| / Y_t
  double bias = 0.0;                            // mean (Y_r − Y_t) / Y_t
  double referenceNoise = 0.0;                  // √(2/π)·mean(σ_i / Y_t)
  double meanTraced = 0.0, meanRendered = 0.0;  // W/(sr·m²), luminance
};

struct SpherePixels {
  std::vector<uint8_t> keep;
  std::vector<glm::vec3> position, normal;  // centre hit, interpolated shading normal
};

// Pixels whose centre and four near-corner points all hit the sphere instance.
SpherePixels findSpherePixels(const Scene& scene, const WorldGeometry& geometry,
                              const RayKernel& kernel, const Camera& camera) {
  const std::vector<std::size_t> sphere = dynamicInstancesNamed(scene, "sphere");
  SpherePixels s;
  const std::size_t n = static_cast<std::size_t>(kSize) * kSize;
  s.keep.assign(n, 0), s.position.resize(n), s.normal.resize(n);
  constexpr float kInset = 0.02f;
  const float offsets[5][2] = {{0.5f, 0.5f},
                               {kInset, kInset},
                               {1 - kInset, kInset},
                               {kInset, 1 - kInset},
                               {1 - kInset, 1 - kInset}};
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * kSize + x;
      bool all = true;
      for (int k = 0; k < 5 && all; ++k) {
        const Ray ray = cameraRay(camera, kSize, kSize, x + offsets[k][0], y + offsets[k][1]);
        const Hit hit = kernel.intersect(ray);
        all = hit.valid() && geometry.triangleInstance[hit.triangle] == sphere[0];
        if (all && k == 0) {
          const glm::uvec3 t = geometry.triangles[hit.triangle];
          s.position[i] = ray.origin + hit.t * ray.direction;
          s.normal[i] =
              glm::normalize((1 - hit.u - hit.v) * geometry.normals[t.x] +
                             hit.u * geometry.normals[t.y] + hit.v * geometry.normals[t.z]);
        }
      }
      s.keep[i] = all ? 1 : 0;
    }
  return s;
}

// Compared in kBlock × kBlock blocks whose pixels are all sphere pixels: both images are
// averaged over the block (the renderer's smooth answer loses nothing; the tracer's noise falls
// by kBlock), then as tests/render/indirect_accuracy.h per block. The pixels' samplers are
// independent, so a block's σ is sqrt(Σ σ_i²)/n.
Comparison compare(const Image& rendered, const Image& traced, const Image& stdError,
                   const std::vector<uint8_t>& keep) {
  Comparison c;
  double sumError = 0, sumBias = 0, sumSigma = 0, sumT = 0, sumR = 0;
  for (int by = 0; by + kBlock <= kSize; by += kBlock)
    for (int bx = 0; bx + kBlock <= kSize; bx += kBlock) {
      double yt = 0, yr = 0, variance = 0;
      bool all = true;
      for (int y = by; y < by + kBlock; ++y)
        for (int x = bx; x < bx + kBlock; ++x) {
          const std::size_t i = static_cast<std::size_t>(y) * kSize + x;
          all = all && keep[i];
          yt += luminance(traced.pixels[i]);
          yr += luminance(rendered.pixels[i]);
          // σ of the luminance ≤ Σ_c w_c σ_c (the channels' errors are correlated).
          const glm::vec3 s = stdError.pixels[i];
          const double sigma = luminance(glm::dvec3(s));
          variance += sigma * sigma;
        }
      const double n = kBlock * kBlock;
      yt /= n, yr /= n;
      if (!all || !(yt > 0.0)) continue;
      sumError += std::abs(yr - yt) / yt;
      sumBias += (yr - yt) / yt;
      sumSigma += std::sqrt(variance) / n / yt;
      sumT += yt, sumR += yr;
      ++c.blocks;
    }
  if (c.blocks == 0) return c;
  const double n = static_cast<double>(c.blocks);
  c.error = sumError / n, c.bias = sumBias / n;
  c.referenceNoise = std::sqrt(2.0 / 3.14159265358979) * sumSigma / n;
  c.meanTraced = sumT / n, c.meanRendered = sumR / n;
  return c;
}

fs::path scenePath() {
  return fs::path(BOUNCE_SOURCE_DIR) / "content/cornell_box_dynamic/cornell_box_dynamic.gltf";
}

// What the tests share per position: the scene as the tools see it, its sphere pixels and the
// path-traced reference (traced once per test program).
struct Placement {
  fs::path wrapper;  // the .json the tools are given
  Scene scene;       // loaded from it, sphere moved
  SpherePixels pixels;
  Image traced, stdError;  // bounce-trace --indirect-only, W/(sr·m²)
};

class DynamicSphere : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // One folder per process: CTest runs the suite's tests as parallel processes, and each
    // removes its folder when it ends.
    dir_ = fs::temp_directory_path() /
           ("bounce_dynamic_sphere_test_" + std::to_string(static_cast<long>(getpid())));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    // Lightmap small and quick (the sphere does not read it); VPLs as content/CMakeLists.txt
    // bakes the scene (kBakeVpls).
    run(tool("bounce-bake") + " " + quote(scenePath()) + " -o " + quote(dir_ / "box.bake") +
            " --quiet --spp 16 --texel-budget 1024 --vpls " + std::to_string(kBakeVpls),
        dir_ / "bake.log");
    for (std::size_t p = 0; p < std::size(kPositions); ++p) place(p);
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  // A wrapper (.json) around the scene whose camera looks at the sphere from the Cornell eye,
  // the sphere filling 1/1.02 of the frame's height; then the reference trace.
  static void place(std::size_t p) {
    const Position& at = kPositions[p];
    Placement& m = placements_[p];
    m.wrapper = dir_ / ("sphere" + std::to_string(p) + ".json");
    const float distance = glm::length(at.centre - kEye);
    const float yfov = 2.0f * std::asin(1.02f * kRadius / distance);
    const nlohmann::json doc = {{"model", scenePath().string()},
                                {"camera",
                                 {{"name", "at_sphere"},
                                  {"position", {kEye.x, kEye.y, kEye.z}},
                                  {"target", {at.centre.x, at.centre.y, at.centre.z}},
                                  {"yfov", yfov},
                                  {"znear", 0.01},
                                  {"zfar", 10.0}}}};
    std::ofstream(m.wrapper) << doc.dump(1);
    const fs::path traced = dir_ / "traced.exr", error = dir_ / "error.exr";
    run(tool("bounce-trace") + " " + quote(m.wrapper) + moveFlag(at.centre) + size() +
            " --indirect-only --spp " + std::to_string(kSpp) + " --quiet --out " + quote(traced) +
            " --std-error " + quote(error),
        dir_ / "trace.log");
    m.scene = loadScene(m.wrapper);
    moveInstance(m.scene, {"sphere", at.centre});
    const WorldGeometry geometry = flatten(m.scene);
    const auto kernel = makeRayKernel(geometry, RayBackend::Embree);
    m.pixels = findSpherePixels(m.scene, geometry, *kernel, m.scene.cameras.at(0));
    m.traced = readExr(traced);
    m.stdError = readExr(error);
  }

  static std::string size() {
    return " --width " + std::to_string(kSize) + " --height " + std::to_string(kSize);
  }

  static Bake bake(const Scene& scene) { return readBake(dir_ / "box.bake", scene); }
  static float clampDistance(const Bake& bake) {
    return static_cast<float>(bake.manifest.vpls.value().clampDistance);
  }

  static fs::path dir_;
  static Placement placements_[std::size(kPositions)];
};
fs::path DynamicSphere::dir_;
Placement DynamicSphere::placements_[std::size(kPositions)];

void report(const char* who, const Position& at, const Comparison& c) {
  std::printf(
      "%-26s sphere %-20s: %zu blocks, traced %.5f W/(sr m^2), got %.5f, mean |rel error| "
      "%5.2f%%, bias %+6.2f%% (tracer noise adds <= %.2f%%)\n",
      who, at.what, c.blocks, c.meanTraced, c.meanRendered, 100 * c.error, 100 * c.bias,
      100 * c.referenceNoise);
}

// L = ρ/π · E_vpl at the sphere pixels' centre hits (visibility: `kernel`, nullptr for none).
Image gather(const Placement& m, std::span<const Vpl> vpls, const RayKernel* kernel, float r) {
  const Scene& scene = m.scene;
  const std::size_t sphere = dynamicInstancesNamed(scene, "sphere").front();
  const glm::vec3 albedo =
      scene.materials.at(scene.meshes.at(scene.instances[sphere].mesh).material).albedo;
  Image image(kSize, kSize);
  for (std::size_t i = 0; i < m.pixels.keep.size(); ++i)
    if (m.pixels.keep[i])
      image.pixels[i] =
          albedo * kInvPi *
          glm::vec3(gatherVplIrradiance(vpls, m.pixels.position[i], m.pixels.normal[i], kernel, r)
                        .irradiance);
  return image;
}

// First-bounce VPLs scaled by the fraction of the emitters the dynamic instances hide from them
// (a grid of 28 points per emitter triangle): the dynamic object's own shadow on the surfaces
// the VPLs stand for, which the bake (run without it) cannot know. Later bounces unchanged.
std::vector<Vpl> shadowedByDynamics(const Scene& scene, const VplSet& set) {
  const WorldGeometry all = flatten(scene);
  Scene dynamics = scene;
  std::erase_if(dynamics.instances,
                [](const Instance& i) { return i.mobility != Mobility::Dynamic; });
  const WorldGeometry geometry = flatten(dynamics);
  const auto kernel = makeRayKernel(geometry, RayBackend::Embree);
  std::vector<glm::vec3> lightPoints;
  for (std::size_t t = 0; t < all.triangleCount(); ++t) {
    if (!scene.materials[all.triangleMaterial[t]].isEmissive()) continue;
    const glm::uvec3 tri = all.triangles[t];
    for (int a = 0; a < 7; ++a)
      for (int b = 0; a + b < 7; ++b) {
        const float u = (a + 1.0f / 3) / 7.5f, v = (b + 1.0f / 3) / 7.5f;
        lightPoints.push_back((1 - u - v) * all.positions[tri.x] + u * all.positions[tri.y] +
                              v * all.positions[tri.z]);
      }
  }
  std::vector<Vpl> out = set.vpls;
  for (std::size_t k = 0; k < out.size(); ++k) {
    if (set.bounce[k] != 1) continue;
    int visible = 0;
    const glm::vec3 o = out[k].position + 1e-4f * out[k].normal;
    for (const glm::vec3& q : lightPoints)
      visible += kernel->occluded(Ray{o, 0.0f, glm::normalize(q - o), glm::length(q - o)}) ? 0 : 1;
    out[k].flux *= static_cast<float>(visible) / static_cast<float>(lightPoints.size());
  }
  return out;
}

// GL-free: what VPLs can do for the sphere, gathered at the same hit points as the renderer
// draws (gatherVplIrradiance, the formula the renderer's VPL term implements), against the
// tracer. Several VPL sets, so the error's parts can be told apart:
//   baked, no visibility      what a renderer without VPL shadows gets from the bake's VPLs;
//   baked, exact visibility   the same with every VPL ray-tested (what VPL shadow maps approach);
//   baked, sphere's shadow    first-bounce VPLs dimmed by the sphere's shadow from the light;
//   traced with the sphere    VPLs generated with the sphere in place (a run-time regeneration),
//                             at the bake's count N and at 4N (clamp r/2, since r ∝ 1/√N).
// The bake leaves the dynamic sphere out, so its VPLs also stand on the floor and blocks right
// under the sphere, which the sphere shadows: the first two overestimate the sphere (bias
// +13..+39% here). The others show what the VPL estimate is worth once the VPLs know the
// sphere: VPL noise and the clamp (N ≈ 4096 VPLs from ~1700 light paths: 3-11% on the sphere;
// 4N: a few %). Asserted: the reference is quiet enough, and 4N VPLs traced with the sphere
// meet the 10% (the comparison itself is sound); the rest is printed for docs/vpl_measurements.md.
TEST_F(DynamicSphere, VplErrorBudgetAgainstThePathTracer) {
#ifdef __SANITIZE_ADDRESS__
  // About 27 s under AddressSanitizer, most of it the reference path tracer's samples; the
  // same code runs under ASan in the smaller tests. CI's sanitizer stage keeps to 30 minutes.
  GTEST_SKIP() << "an accuracy measurement: run in the release build";
#endif
  for (std::size_t p = 0; p < std::size(kPositions); ++p) {
    const Placement& m = placements_[p];
    const Position& at = kPositions[p];
    const Bake baked = bake(m.scene);
    ASSERT_TRUE(baked.vpls.has_value());
    const float r = clampDistance(baked);
    const WorldGeometry geometry = flatten(m.scene);
    const auto kernel = makeRayKernel(geometry, RayBackend::Embree);
    std::printf("%s: %zu VPLs, clamp distance %.4f m\n", at.what, baked.vpls->size(), r);

    const Comparison none =
        compare(gather(m, *baked.vpls, nullptr, r), m.traced, m.stdError, m.pixels.keep);
    report("baked, no visibility", at, none);
    const Comparison exact =
        compare(gather(m, *baked.vpls, kernel.get(), r), m.traced, m.stdError, m.pixels.keep);
    report("baked, exact visibility", at, exact);
    // The rows at bounce-bake's default N (VplSettings{}) use the clamp distance of that
    // count, 2r (r ∝ 1/√N; the bake has 4N VPLs).
    const float rDefault = 2.0f * r;
    const Scene statics = staticScene(m.scene);
    const WorldGeometry staticGeometry = flatten(statics);
    const auto staticKernel = makeRayKernel(staticGeometry, RayBackend::Embree);
    const VplSet set = generateVpls(statics, staticGeometry, *staticKernel, VplSettings{});
    const Comparison dimmed =
        compare(gather(m, shadowedByDynamics(m.scene, set), kernel.get(), rDefault), m.traced,
                m.stdError, m.pixels.keep);
    report("default N, sphere's shadow", at, dimmed);
    // The bake's light paths cut where the sphere blocks them (vpl_runtime/vpl_occlusion.h, what
    // the renderer does), gathered without visibility (the renderer's VPL shadows are off by
    // default): at N and at the bake's 4N (the same seed and settings as bounce-bake).
    const std::vector<VplOccluder> sphere = dynamicVplOccluders(m.scene);
    const auto cut = [&](const VplSet& from) {
      std::vector<Vpl> out = from.vpls;
      const std::vector<uint8_t> alive = vplAliveMask(out, sphere);
      for (std::size_t i = 0; i < out.size(); ++i)
        if (alive[i] == 0) out[i].flux = glm::vec3(0.0f);
      return out;
    };
    report("default N, paths cut by the sphere", at,
           compare(gather(m, cut(set), nullptr, rDefault), m.traced, m.stdError, m.pixels.keep));
    VplSettings bakeSettings;
    bakeSettings.maxVpls = kBakeVpls;
    const VplSet bakeSet = generateVpls(statics, staticGeometry, *staticKernel, bakeSettings);
    EXPECT_EQ(bakeSet.vpls.size(), baked.vpls->size());
    report("bake (4N), paths cut by the sphere", at,
           compare(gather(m, cut(bakeSet), nullptr, r), m.traced, m.stdError, m.pixels.keep));
    // The same with a ray per VPL: what the renderer's VPL shadow cubes approach.
    report("bake (4N), cut, exact visibility", at,
           compare(gather(m, cut(bakeSet), kernel.get(), r), m.traced, m.stdError, m.pixels.keep));
    Scene withSphere = m.scene;
    for (Instance& instance : withSphere.instances) instance.mobility = Mobility::Static;
    const VplSet own = generateVpls(withSphere, geometry, *kernel, VplSettings{});
    report(
        "default N, traced with the sphere", at,
        compare(gather(m, own.vpls, kernel.get(), rDefault), m.traced, m.stdError, m.pixels.keep));
    VplSettings more;
    more.maxVpls = kBakeVpls;
    const VplSet many = generateVpls(withSphere, geometry, *kernel, more);
    const Comparison manyWith =
        compare(gather(m, many.vpls, kernel.get(), r), m.traced, m.stdError, m.pixels.keep);
    report("4N, traced with the sphere", at, manyWith);
    report("4N, traced with the sphere, no visibility", at,
           compare(gather(m, many.vpls, nullptr, r), m.traced, m.stdError, m.pixels.keep));

    // The same with the sphere black (albedo 0): paths end at it, as the cut ends them; the
    // difference to the row above is the light the sphere itself reflects (into the room and
    // back onto itself), which the cut set cannot carry.
    Scene blackSphere = withSphere;
    const uint32_t black = static_cast<uint32_t>(blackSphere.materials.size());
    blackSphere.materials.push_back(Material{});
    blackSphere.materials.back().albedo = glm::vec3(0.0f);
    for (const Instance& instance : m.scene.instances)
      if (instance.mobility == Mobility::Dynamic)
        blackSphere.meshes[instance.mesh].material = black;
    const WorldGeometry blackGeometry = flatten(blackSphere);
    const auto blackKernel = makeRayKernel(blackGeometry, RayBackend::Embree);
    const VplSet manyBlack = generateVpls(blackSphere, blackGeometry, *blackKernel, more);
    report("4N, traced with a black sphere", at,
           compare(gather(m, manyBlack.vpls, nullptr, r), m.traced, m.stdError, m.pixels.keep));

    EXPECT_GE(manyWith.blocks, 12u) << at.what;
    EXPECT_LE(manyWith.referenceNoise, 0.035)
        << at.what << ": the tracer is too noisy at " << kSpp << " spp";
    EXPECT_LE(manyWith.error, 0.10) << at.what;
  }
}

// The dynamic sphere against the path tracer through the tools: bounce-render --mode indirect (the
// dynamic sphere gets ρ/π·E_vpl from VPLs) against bounce-trace --indirect-only, both with --move.
// bounce-render traces the VPLs again with the sphere at its --move position (--dynamic-vpls
// retrace, the default; vpl/vpl_retrace.h) with the bake's count rule (4N VPLs, kBakeVpls, so that
// VPL noise stays within the budget): they carry the sphere's shadow on the room and the light it
// reflects into the room and back onto itself.
// VPL shadow maps on (bounce-render's default: 4 cubes per part of each VPL group). Measured
// 6.64 / 1.69 / 6.78% (bias +0.4 / −0.5 / −6.1%); without VPL shadows 8.58 / 8.85 / 6.71%.
// The VPL set is one random draw: the GL-free gather of re-traced sets with exact visibility over
// seeds 1-5 gives 2.9-8.3% (VPL noise and the tracer's ≤ 3%), so the 10% is met with a margin
// for any seed, not just this one.
// Before: the bake's VPLs as they were (traced without the sphere) 45.1 / 27.0 / 30.9%; their
// paths cut where the sphere blocks them (--dynamic-vpls cut) 13.9 / 11.2 / 21.3%: without the
// light the sphere reflects (7-19% of its indirect light). Injected --dynamic-vpls cut: fails.
TEST_F(DynamicSphere, RendererLightsTheSphereWithin10PercentOfThePathTracer) {
#ifdef __SANITIZE_ADDRESS__
  // About 22 s under AddressSanitizer, most of it the path tracer's reference or the bake's
  // samples; the same code runs under ASan in the smaller tests. CI's sanitizer stage keeps to
  // its 30 minutes.
  GTEST_SKIP() << "an accuracy measurement: run in the release build";
#endif
  for (std::size_t p = 0; p < std::size(kPositions); ++p) {
    const Placement& m = placements_[p];
    const Position& at = kPositions[p];
    const fs::path rendered = dir_ / "rendered.exr";
    ASSERT_EQ(
        run(tool("bounce-render") + " " + quote(m.wrapper) + moveFlag(at.centre) + size() +
                " --bake " + quote(dir_ / "box.bake") + " --mode indirect --out " + quote(rendered),
            dir_ / "render.log"),
        0);
    const Comparison c = compare(readExr(rendered), m.traced, m.stdError, m.pixels.keep);
    report("renderer (indirect mode)", at, c);
    EXPECT_GE(c.blocks, 12u) << at.what;
    EXPECT_LE(c.referenceNoise, 0.035) << at.what;
    EXPECT_LE(c.error, 0.10) << at.what;
  }
}

// The VPL clamp at its singularity: content/vpl_corner is a concave box corner (floor and
// two walls meeting at the origin, a 1 W/sr point light): every face sees every other, so VPL
// light there has no visibility error, only VPL noise and the clamp. bounce-render --mode vpl
// draws every surface's indirect light from the bake's VPLs (count from bounce-bake's defaults);
// bounce-trace --indirect-only is the truth.
//
// The bound. The renderer adds, per VPL, Φ/π · cosθ_y · cosθ_x / max(d², r²) · ρ_x/π; the
// clamp replaces a VPL closer than r by (at most) the disc of radius r it stands for: a disc of
// radiance L = Φ/(π·πr²) gives πL·r²/(r² + d²) on its axis, = Φ/(πr²) at d = 0 (docs/vpl.md).
// In this corner a VPL lights only the other two faces (same-face VPLs have cosθ_x = 0), and for
// faces at right angles cosθ_x·cosθ_y = a·b/d² ≤ a·b/(a² + b²) ≤ 1/2 (a, b the distances of x and
// y from the common edge). So one clamped VPL adds at most c(x) = ρ_x/π · Φ_max/(2π r²), whatever
// its distance; unclamped, a VPL 1 mm from x adds up to (r/1 mm)² ≈ 50 × that. The test: no pixel
// exceeds the truth by more than c (luminance, Σ_ch w_ch ρ_ch Φ_max,ch) beyond the tracer's
// noise (4σ per pixel: 4096 pixels, p ≈ 3·10⁻⁵ each). The energy the clamp removed is read from
// bounce-render's report and from --mode vpl-clamp.
class VplCorner : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / "bounce_vpl_corner_test";
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(VplCorner, NoPixelExceedsTheTruthByMoreThanOneClampedVpl) {
  constexpr int kFrame = 64, kCornerSpp = 256;
  const fs::path scene = fs::path(BOUNCE_SOURCE_DIR) / "content/vpl_corner/vpl_corner.gltf";
  const fs::path wrapper = dir_ / "corner.json", bakeDir = dir_ / "corner.bake";
  std::ofstream(wrapper) << nlohmann::json{
      {"model", scene.string()},
      {"camera",
       {{"name", "corner"},
        {"position", {0.75, 0.42, 0.75}},
        {"target", {0.06, 0.07, 0.06}},
        {"yfov", 0.75},
        {"znear", 0.01},
        {"zfar", 10.0}}}}.dump(1);
  const std::string size =
      " --width " + std::to_string(kFrame) + " --height " + std::to_string(kFrame);
  ASSERT_EQ(run(tool("bounce-bake") + " " + quote(scene) + " -o " + quote(bakeDir) +
                    " --quiet --spp 16 --texel-budget 1024",
                dir_ / "bake.log"),
            0);
  ASSERT_EQ(run(tool("bounce-trace") + " " + quote(wrapper) + size + " --indirect-only --spp " +
                    std::to_string(kCornerSpp) + " --quiet --out " + quote(dir_ / "t.exr") +
                    " --std-error " + quote(dir_ / "s.exr"),
                dir_ / "trace.log"),
            0);
  const fs::path log = dir_ / "render.log";
  ASSERT_EQ(run(tool("bounce-render") + " " + quote(wrapper) + size + " --bake " + quote(bakeDir) +
                    " --mode vpl --out " + quote(dir_ / "vpl.exr"),
                log),
            0);
  std::ifstream logFile(log);
  std::string line, report;
  while (std::getline(logFile, line))
    if (line.find("VPL clamp removed") != std::string::npos) report = line;
  std::printf("%s\n", report.c_str());
  double removedPercent = -1.0;
  const std::size_t at = report.find("removed ");
  if (at != std::string::npos) removedPercent = std::atof(report.c_str() + at + 8);
  EXPECT_GE(removedPercent, 0.0) << "bounce-render did not report the clamped energy";
  ASSERT_EQ(run(tool("bounce-render") + " " + quote(wrapper) + size + " --bake " + quote(bakeDir) +
                    " --mode vpl-clamp --out " + quote(dir_ / "clamp.exr"),
                log),
            0);

  const Scene loaded = loadScene(wrapper);
  const Bake bake = readBake(bakeDir, loaded);
  ASSERT_TRUE(bake.vpls.has_value());
  const float r = static_cast<float>(bake.manifest.vpls.value().clampDistance);
  glm::vec3 fluxMax(0.0f);
  for (const Vpl& vpl : *bake.vpls) fluxMax = glm::max(fluxMax, vpl.flux);
  const Image truth = readExr(dir_ / "t.exr"), sigma = readExr(dir_ / "s.exr");
  const Image vpl = readExr(dir_ / "vpl.exr"), clamp = readExr(dir_ / "clamp.exr");
  const WorldGeometry geometry = flatten(loaded);
  const auto kernel = makeRayKernel(geometry, RayBackend::Embree);
  const Camera& camera = loaded.cameras.at(0);

  double worst = -1e30, worstUnclamped = -1e30, sumVpl = 0, sumTruth = 0, removedMax = 0;
  std::size_t pixels = 0, worstPixel = 0;
  for (int y = 0; y < kFrame; ++y)
    for (int x = 0; x < kFrame; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * kFrame + x;
      const Hit hit = kernel->intersect(cameraRay(camera, kFrame, kFrame, x + 0.5f, y + 0.5f));
      if (!hit.valid()) continue;
      const glm::vec3 rho = loaded.materials.at(geometry.triangleMaterial[hit.triangle]).albedo;
      const double c = luminance(rho * fluxMax) / (2.0 * kPi * kPi * r * r);
      const glm::vec3 s = sigma.pixels[i];
      const double noise = 4.0 * luminance(glm::dvec3(s));
      const double excess = luminance(vpl.pixels[i]) - luminance(truth.pixels[i]) - noise;
      // Unclamped, approximately: the removed part (vpl-clamp's green: lum(E_removed)/π on a
      // white surface) times the surface's luminance albedo.
      const double unclamped = excess + luminance(rho) * clamp.pixels[i].g;
      if (excess / c > worst) worst = excess / c, worstPixel = i;
      worstUnclamped = std::max(worstUnclamped, unclamped / c);
      removedMax = std::max(removedMax, static_cast<double>(clamp.pixels[i].g));
      sumVpl += luminance(vpl.pixels[i]), sumTruth += luminance(truth.pixels[i]);
      ++pixels;
    }
  std::printf(
      "%zu VPLs, r = %.4f m, one clamped VPL adds at most %.3f W/(sr m^2) on white; "
      "%zu pixels: VPL %.4f vs traced %.4f W/(sr m^2) mean (luminance); largest excess over "
      "truth + 4 sigma: %.3f of the bound (pixel %zu: VPL %.4f, traced %.4f); without the "
      "clamp ~%.1f of it; largest removed E/pi %.3f W/(sr m^2)\n",
      bake.vpls->size(), static_cast<double>(r),
      luminance(fluxMax) / (2.0 * kPi * kPi * static_cast<double>(r) * r), pixels, sumVpl / pixels,
      sumTruth / pixels, worst, worstPixel, static_cast<double>(luminance(vpl.pixels[worstPixel])),
      static_cast<double>(luminance(truth.pixels[worstPixel])), worstUnclamped, removedMax);
  EXPECT_GT(pixels, 2000u);
  EXPECT_LE(worst, 1.0) << "a pixel exceeds the truth by more than one clamped VPL";
  EXPECT_GT(removedMax, 0.0) << "the clamp removed nothing at the corner";
}

// Both tools read --move through engine/scene/instance_move.h: the same refusals, naming the
// scene, the name and the dynamic instances; and a static scene instance cannot be moved.
TEST(MoveFlag, BothToolsRefuseStaticAndUnknownInstancesNamingTheScene) {
  const fs::path dir = fs::temp_directory_path() / "bounce_move_flag_test";
  fs::create_directories(dir);
  const fs::path scene = scenePath();
  for (const char* program : {"bounce-render", "bounce-trace"}) {
    for (const auto& [name, expected] :
         {std::pair<std::string, std::string>{"floor", "instance 'floor' is static"},
          std::pair<std::string, std::string>{"lamp", "has no instance 'lamp'"}}) {
      const fs::path log = dir / "out.log";
      const std::string own = tool(program) + " " + quote(scene) + " --move " + name +
                              " 0.2 0.2 0.2 --width 8 --height 8 --out " + quote(dir / "x.exr") +
                              " > " + quote(log) + " 2>&1";
      const int status = std::system(own.c_str());
      EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 1) << own;
      std::ifstream in(log);
      std::stringstream text;
      text << in.rdbuf();
      EXPECT_NE(text.str().find(scene.string()), std::string::npos) << text.str();
      EXPECT_NE(text.str().find(expected), std::string::npos) << text.str();
      EXPECT_NE(text.str().find("dynamic instances: 'sphere'"), std::string::npos) << text.str();
      EXPECT_FALSE(fs::exists(dir / "x.exr")) << program << " wrote an image";
    }
  }
  fs::remove_all(dir);
}

// A --move use takes exactly its four words: the scene path right after it stays the scene
// (CLI11 2.1 let the use run on and swallow it: "scene is required").
TEST(MoveFlag, AUseStopsAfterItsFourWords) {
  const fs::path dir = fs::temp_directory_path() / "bounce_move_words_test";
  fs::create_directories(dir);
  for (const auto& [program, extra] : {std::pair<std::string, std::string>{"bounce-render", ""},
                                       {"bounce-trace", " --spp 1 --quiet"}}) {
    const fs::path out = dir / "x.exr";
    fs::remove(out);
    EXPECT_EQ(run(tool(program) + " --move sphere 0.3 0.3 0.2 " + quote(scenePath()) +
                      " --width 4 --height 4" + extra + " --out " + quote(out),
                  dir / "out.log"),
              0)
        << program;
    EXPECT_TRUE(fs::exists(out)) << program;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace bounce
