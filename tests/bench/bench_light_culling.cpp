// Light culling (render/light_culling.h): frame time against the number of point lights, with
// culling on and off, side by side in one run on one machine (offscreen, OSMesa), and what the
// cut-off costs in accuracy (docs/renderer.md, "Light culling").
//
//   bench_light_culling [--out FILE.csv] [--width W] [--height H] [--frames N]
//                       [--counts 8,64,256,1024] [--exposure EV]
//
// Scenes: tests/render/light_field_scene.h's field (N point lights 5 m apart, 0.05–0.5 W/sr,
// 0.5–1.5 m over a floor 5·(√N + 1) m wide, the camera 3 m up at one edge looking across), and
// content/many_lights/many_lights.gltf (64 point lights + 1 area light in a 12 m room, its own
// camera). One sample per pixel, shadows on (the renderer's defaults), no bake. Per scene:
//   ms_on, ms_off          median wall time of render + glFinish (no readback) over N frames
//                          after one warm-up (the driver's shader JIT, the shadow maps), culling
//                          on and off (an unculled 1024-light frame takes minutes on llvmpipe);
//   cpu_ms_on, cpu_ms_off  the same frames' process CPU time per frame (all llvmpipe threads);
//   grid_ms                of that, the CPU building the lists (median of 5: reaches, grid, lists);
//   lights_per_cluster     mean punctual-list length; max_lights the longest;
//   max_abs, mean_abs      |culled − unculled| over the pixels, W/(sr·m²) (brightest channel);
//   max_codes              the largest difference of the two frames tone-mapped at EV (8-bit
//                          sRGB code values, PNG files).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "frame_time.h"
#include "gl/draw_state.h"
#include "gl/shader.h"
#include "image/tonemap.h"
#include "light_field_scene.h"
#include "render/light_reach.h"
#include "render/punctual_lights.h"
#include "render/view.h"
#include "scene/area_lights.h"
#include "scene/load.h"
#include "support/test_context.h"

namespace bounce::test {
namespace {

struct Options {
  std::string out = "bench_light_culling.csv";
  int width = 1280, height = 720, frames = 2;
  std::vector<int> counts = {8, 64, 256, 1024};
  float exposure = 0.0f;
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (i + 1 >= argc) {
      std::fprintf(stderr, "bench_light_culling: %s needs a value\n", flag.c_str());
      std::exit(2);
    }
    const std::string value = argv[++i];
    if (flag == "--out") {
      o.out = value;
    } else if (flag == "--width") {
      o.width = std::stoi(value);
    } else if (flag == "--height") {
      o.height = std::stoi(value);
    } else if (flag == "--frames") {
      o.frames = std::stoi(value);
    } else if (flag == "--exposure") {
      o.exposure = std::stof(value);
    } else if (flag == "--counts") {
      o.counts.clear();
      std::stringstream stream(value);
      for (std::string part; std::getline(stream, part, ',');) o.counts.push_back(std::stoi(part));
    } else {
      std::fprintf(stderr, "bench_light_culling: unknown flag %s\n", flag.c_str());
      std::exit(2);
    }
  }
  return o;
}

// The CPU's part of a culled frame, as LightCulling::update does it, median of 5.
double gridMilliseconds(const Scene& scene, const Camera& camera, int width, int height,
                        float floor) {
  std::vector<double> ms;
  const PunctualLights lights(scene);
  const AreaLightSet area = sceneAreaLights(scene);
  Box bounds;
  for (const Instance& instance : scene.instances)
    for (const glm::vec3& p : scene.meshes[instance.mesh].positions)
      bounds.grow(glm::vec3(instance.transform * glm::vec4(p, 1.0f)));
  for (int run = 0; run < 5; ++run) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<LightReach> punctual;
    for (std::size_t i = 0; i < lights.size(); ++i)
      punctual.push_back(punctualReach(lights.light(i), lights.drawnPower(i), floor));
    const std::vector<LightReach> areas = areaReaches(area, floor);
    const glm::vec2 depths = viewDepthRange(camera, bounds);
    const ClusterGrid grid = makeClusterGrid(camera, width, height, depths.x, depths.y);
    const LightGridLists lists = assignLights(grid, punctual, areas);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                     .count());
    if (lists.headers.empty()) std::abort();
  }
  std::sort(ms.begin(), ms.end());
  return ms[ms.size() / 2];
}

// frame_time.h's frames (warm-up, then render + glFinish); `last` gets the last frame's radiance.
FrameTime timeFrames(ForwardRenderer& renderer, const Camera& camera, gl::RenderTarget& target,
                     int frames, Image& last) {
  const FrameTime t = frameMilliseconds(renderer, camera, target, frames);
  last = target.read();
  return t;
}

struct Row {
  std::string scene;
  std::size_t lights = 0;
  FrameTime on, off;
  double gridMs = 0.0, perCluster = 0.0;
  std::size_t maxLights = 0;
  double maxAbs = 0.0, meanAbs = 0.0;
  int maxCodes = 0;
};

Row measure(const std::string& name, const Scene& scene, const Camera& camera, const Options& o) {
  Row row;
  row.scene = name;
  row.lights = scene.lights.size();
  RendererSettings settings;
  settings.lightCulling.irradianceFloor = irradianceFloorForExposure(o.exposure);
  gl::RenderTarget target(o.width, o.height, 1);
  Image culled, unculled;
  {
    ForwardRenderer renderer(scene, gl::shaderDirectory(), settings);
    row.on = timeFrames(renderer, camera, target, o.frames, culled);
    const LightGridStats stats = renderer.lightGridStats();
    row.perCluster = static_cast<double>(stats.punctualEntries) / stats.clusters;
    row.maxLights = stats.maxPunctual;
  }
  settings.lightCulling.enabled = false;
  {
    ForwardRenderer renderer(scene, gl::shaderDirectory(), settings);
    row.off = timeFrames(renderer, camera, target, o.frames, unculled);
  }
  row.gridMs =
      gridMilliseconds(scene, camera, o.width, o.height, settings.lightCulling.irradianceFloor);
  for (std::size_t i = 0; i < culled.pixels.size(); ++i) {
    const glm::vec3 d = glm::abs(unculled.pixels[i] - culled.pixels[i]);
    const double m = std::max({d.r, d.g, d.b});
    row.maxAbs = std::max(row.maxAbs, m);
    row.meanAbs += m / static_cast<double>(culled.pixels.size());
    const glm::vec3 a = toneMap(culled.pixels[i], o.exposure) * 255.0f;
    const glm::vec3 b = toneMap(unculled.pixels[i], o.exposure) * 255.0f;
    for (int k = 0; k < 3; ++k)
      row.maxCodes = std::max(row.maxCodes, std::abs(static_cast<int>(std::lround(a[k])) -
                                                     static_cast<int>(std::lround(b[k]))));
  }
  std::fprintf(stderr,
               "%s: %zu lights: on %.1f ms (cpu %.1f, lists %.2f), off %.1f ms (cpu %.1f); "
               "%.1f lights per cluster (max %zu); |diff| max %.3g mean %.3g, %d codes\n",
               name.c_str(), row.lights, row.on.wallMs, row.on.cpuMs, row.gridMs, row.off.wallMs,
               row.off.cpuMs, row.perCluster, row.maxLights, row.maxAbs, row.meanAbs, row.maxCodes);
  return row;
}

int run(const Options& o) {
  testContext();
  std::vector<Row> rows;
  for (const int count : o.counts) {
    const LightField field = lightField(count, 5.0f, 0.05f, 0.5f);
    rows.push_back(measure("field", field.scene, field.camera, o));
  }
  const Scene many =
      loadScene(std::string(BOUNCE_SOURCE_DIR) + "/content/many_lights/many_lights.gltf");
  rows.push_back(measure("many_lights", many, many.cameras.at(0), o));
  std::ofstream csv(o.out);
  csv << "scene,lights,width,height,frames,exposure,ms_on,ms_off,cpu_ms_on,cpu_ms_off,grid_ms,"
         "lights_per_cluster,max_lights,max_abs,mean_abs,max_codes\n";
  for (const Row& r : rows)
    csv << r.scene << ',' << r.lights << ',' << o.width << ',' << o.height << ',' << o.frames << ','
        << o.exposure << ',' << r.on.wallMs << ',' << r.off.wallMs << ',' << r.on.cpuMs << ','
        << r.off.cpuMs << ',' << r.gridMs << ',' << r.perCluster << ',' << r.maxLights << ','
        << r.maxAbs << ',' << r.meanAbs << ',' << r.maxCodes << '\n';
  std::fprintf(stderr, "wrote %s\n", o.out.c_str());
  return csv ? 0 : 1;
}

}  // namespace
}  // namespace bounce::test

int main(int argc, char** argv) {
  return bounce::test::run(bounce::test::parse(argc, argv));
}
