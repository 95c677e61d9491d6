// The renderer with a VPL tracer (RendererSettings::vplTracer, vpl/vpl_retrace.h): moving a
// dynamic instance traces the VPLs again with it in place. A grey room with a dynamic box and an
// unequal point light, drawn with --mode vpl (every surface's indirect light from the VPLs):
// after setInstanceTransform the frame equals, bit for bit, the frame of a renderer built with
// the box already there (the trace is deterministic), differs from the frame before, and moving
// back returns the first frame exactly.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "bake_folder/bake_folder.h"
#include "gl/shader.h"
#include "lightmap_scenes.h"
#include "render/forward_renderer.h"
#include "render/vpl_pass.h"
#include "shadow_scenes.h"
#include "vpl/vpl_retrace.h"

namespace bounce::test {
namespace {

Material grey(const char* name, glm::vec3 albedo) {
  Material m;
  m.name = name;
  m.albedo = albedo;
  return m;
}

TEST(VplRetraceRender, MovingADynamicBoxTracesTheVplsAgainWithItThere) {
  testContext();
  Scene scene;
  addQuad(scene, {-1.0f, 0.0f, 1.0f}, {2, 0, 0}, {0, 0, -2}, grey("floor", glm::vec3(0.6f)));
  addQuad(scene, {-1.0f, 0.0f, -1.0f}, {2, 0, 0}, {0, 1.5f, 0},
          grey("wall", {0.7f, 0.2f, 0.2f}));  // faces +z
  addBox(scene, {-0.15f, 0.2f, -0.15f}, {0.15f, 0.5f, 0.15f}, grey("box", {0.2f, 0.7f, 0.3f}));
  const std::size_t box = scene.instances.size() - 1;
  scene.instances[box].mobility = Mobility::Dynamic;
  Light light;
  light.position = {0.3f, 1.2f, 0.4f};
  light.intensity = {2.0f, 1.5f, 1.0f};  // W/sr
  scene.lights.push_back(light);

  Bake bake;
  bake.layout.width = bake.layout.height = 1;
  bake.layout.texelSize = 1.0f;
  bake.irradiance = Image(1, 1);
  bake.manifest = minimalManifest(scene);
  bake.manifest.vpls = BakeManifest::Vpls{.count = 1, .clampDistance = 0.02f};
  bake.vpls = std::vector<Vpl>(1);  // replaced by the trace
  VplSettings vplSettings;
  vplSettings.maxVpls = 1024;
  RendererSettings settings;
  settings.mode = RenderMode::Vpl;
  settings.vpls.shadows.enabled = false;
  auto tracer = std::make_shared<PlacedVplTracer>(scene, vplSettings);
  settings.vplTracer = [tracer](std::span<const glm::mat4> t) { return tracer->trace(t); };

  ForwardRenderer renderer(scene, gl::shaderDirectory(), settings, &bake);
  const glm::mat4 there = glm::translate(glm::mat4(1.0f), glm::vec3(0.4f, 0.0f, -0.5f));
  Scene movedScene = scene;
  movedScene.instances[box].transform = there;
  ForwardRenderer moved(movedScene, gl::shaderDirectory(), settings, &bake);
  EXPECT_GT(renderer.vpls().groups().vplCount(), 100u);

  const Camera camera = downCamera(2.5f, 1.0f);
  constexpr int kSize = 32;
  const Image first = renderer.renderImage(camera, kSize, kSize);
  const Image reference = moved.renderImage(camera, kSize, kSize);
  renderer.setInstanceTransform(box, there);
  const Image after = renderer.renderImage(camera, kSize, kSize);
  std::size_t differ = 0;
  for (std::size_t i = 0; i < after.pixels.size(); ++i) {
    for (int c = 0; c < 3; ++c)
      ASSERT_EQ(after.pixels[i][c], reference.pixels[i][c])
          << "pixel " << i << ": moved, the VPLs were not traced again with the box there";
    if (first.pixels[i] != reference.pixels[i]) ++differ;
  }
  EXPECT_GT(differ, after.pixels.size() / 2) << "moving the box changed almost nothing";
  renderer.setInstanceTransform(box, glm::mat4(1.0f));
  const Image back = renderer.renderImage(camera, kSize, kSize);
  for (std::size_t i = 0; i < back.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) ASSERT_EQ(back.pixels[i][c], first.pixels[i][c]) << "pixel " << i;
}

}  // namespace
}  // namespace bounce::test
