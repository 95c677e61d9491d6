// bounce-atlas: builds the lightmap atlas of a scene (baker/atlas/atlas.h) and reports its size,
// charts and utilisation; optionally draws it as a PNG (one colour per chart) to look at.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <exception>
#include <iostream>
#include <string>

#include "atlas/atlas.h"
#include "atlas/uv_geometry.h"
#include "bake_folder/lightmap_charts.h"
#include "image/image_compare.h"
#include "image/image_io.h"
#include "scene/load.h"

namespace {

// Covered texels in their chart's colour, texels of two charts white, empty texels dark grey;
// each texel `scale` pixels wide.
bounce::Image atlasPicture(const bounce::Atlas& atlas, int scale) {
  const bounce::LightmapLayout& layout = atlas.layout;
  std::vector<int64_t> owner(static_cast<std::size_t>(layout.width) * layout.height, -1);
  const glm::vec2 size(static_cast<float>(layout.width), static_cast<float>(layout.height));
  for (std::size_t r = 0; r < layout.instances.size(); ++r) {
    const auto& uv = layout.instances[r].cornerUv;
    for (std::size_t t = 0; 3 * t < uv.size(); ++t) {
      const uint32_t chart = atlas.triangleChart[r][t];
      bounce::forEachTouchedTexel(uv[3 * t] * size, uv[3 * t + 1] * size, uv[3 * t + 2] * size,
                                  layout.width, layout.height, [&](int x, int y) {
                                    int64_t& o =
                                        owner[static_cast<std::size_t>(y) * layout.width + x];
                                    o = (o >= 0 && o != chart) ? -2 : chart;
                                  });
    }
  }
  bounce::Image picture(layout.width * scale, layout.height * scale);
  for (int y = 0; y < picture.height; ++y)
    for (int x = 0; x < picture.width; ++x) {
      const int64_t o = owner[static_cast<std::size_t>(y / scale) * layout.width + x / scale];
      picture.at(x, y) = o == -1   ? glm::vec3(0.12f)
                         : o == -2 ? glm::vec3(1.0f)
                                   : bounce::chartColour(static_cast<uint32_t>(o));
    }
  return picture;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Builds the lightmap atlas of a scene (charts of every static instance, packed with "
      "padding) and reports its size, chart count and utilisation (covered texels / atlas "
      "texels)."};
  std::string scenePath, pngPath;
  bounce::AtlasSettings settings;
  int scale = 2;
  bool json = false;
  app.add_option("SCENE", scenePath, "scene file (.gltf, .glb, .obj)")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("--texel-size", settings.texelSize,
                 "texel edge on the surface, metres, where extras.bounce.lightmapScale is 1 "
                 "(default: the rule bounce-bake uses: 5 cm, finer on a small scene so it still "
                 "gets 16384 texels; docs/lightmap_atlas.md)")
      ->check(CLI::PositiveNumber);
  app.add_option("--texel-budget", settings.texelBudget,
                 "texels the static surface should cover, instead of the default rule")
      ->check(CLI::PositiveNumber);
  app.add_option("--max-texels", settings.maxTexels,
                 "cap on the texels the static surface takes: beyond it the texels grow, with a "
                 "note")
      ->capture_default_str()
      ->check(CLI::Range(int64_t{16}, int64_t{1} << 28));
  app.add_option("--padding", settings.padding, "texels kept free between charts")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  app.add_option("--max-size", settings.maxSize, "largest atlas edge, texels")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--png", pngPath,
                 "write the atlas as a PNG, one colour per chart (white: texels "
                 "two charts share, which must not happen)");
  app.add_option("--png-scale", scale, "pixels per texel in the PNG")
      ->capture_default_str()
      ->check(CLI::Range(1, 16));
  app.add_flag("--json", json, "print the report as JSON");
  CLI11_PARSE(app, argc, argv);

  try {
    const bounce::Scene scene = bounce::loadScene(scenePath);
    const bounce::Atlas atlas = bounce::buildAtlas(scene, settings);
    const bounce::LightmapLayout& layout = atlas.layout;
    const auto& kinds = atlas.chartKinds;
    std::size_t staticTriangles = 0;  // what the bake's ray kernel holds
    for (const bounce::Instance& instance : scene.instances)
      if (instance.mobility != bounce::Mobility::Dynamic)
        staticTriangles += scene.meshes[instance.mesh].triangleCount();
    const nlohmann::json report = {{"scene", scenePath},
                                   {"width", layout.width},
                                   {"height", layout.height},
                                   {"texelSizeMetres", layout.texelSize},
                                   {"texelRule", atlas.texelRule},
                                   {"weightedAreaSquareMetres", atlas.weightedArea},
                                   {"paddingTexels", layout.padding},
                                   {"staticAreaSquareMetres", atlas.staticArea},
                                   {"staticInstances", layout.instances.size()},
                                   {"staticTriangles", staticTriangles},
                                   {"charts", layout.chartCount},
                                   {"chartKinds",
                                    {{"planar", kinds.planar},
                                     {"conformal", kinds.conformal},
                                     {"meshUv1", kinds.meshUv1},
                                     {"degenerate", kinds.degenerate},
                                     {"bundle", kinds.bundle}}},
                                   {"utilisation", layout.utilisation},
                                   {"notes", atlas.notes}};
    if (json) {
      std::cout << report.dump(2) << "\n";
    } else {
      std::printf("atlas %d x %d texels, %.4g m per texel (%s), %d texels padding\n", layout.width,
                  layout.height, static_cast<double>(layout.texelSize), atlas.texelRule.c_str(),
                  layout.padding);
      std::printf("static surface %.4g m^2 in %zu instances, %zu triangles\n", atlas.staticArea,
                  layout.instances.size(), staticTriangles);
      std::printf(
          "charts %d (planar %d, conformal %d, mesh TEXCOORD_1 %d, degenerate %d, bundles %d)\n",
          layout.chartCount, kinds.planar, kinds.conformal, kinds.meshUv1, kinds.degenerate,
          kinds.bundle);
      std::printf("utilisation %.3f (covered texels / atlas texels)\n",
                  static_cast<double>(layout.utilisation));
      for (const std::string& note : atlas.notes) std::printf("note: %s\n", note.c_str());
    }
    if (!pngPath.empty()) {
      if (layout.width == 0) throw std::runtime_error("the scene has no static surface to draw");
      bounce::writeDisplayPng(pngPath, atlasPicture(atlas, scale));
      if (!json) std::printf("wrote %s\n", pngPath.c_str());
    }
  } catch (const std::exception& e) {
    std::cerr << "bounce-atlas: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
