#include "atlas/atlas.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <tbb/parallel_for.h>

#include "atlas/chart_bundle.h"
#include "atlas/chart_flatten.h"
#include "atlas/chart_mask.h"
#include "atlas/chart_merge.h"
#include "atlas/chart_pack.h"
#include "atlas/chart_segment.h"
#include "atlas/mask_pack.h"
#include "atlas/mesh_uv1.h"
#include "atlas/texel_density.h"
#include "atlas/uv_geometry.h"
#include "scene/static_scene.h"

namespace bounce {
namespace {

// Slack below which a chart's extent is not rounded up to one more texel (its last texel would
// hold a sliver narrower than 1 % of a texel).
constexpr float kExtentSlack = 0.01f;
// Charts covering fewer texels than this merge across folds with small neighbours.
constexpr double kSmallChartTexels = 16.0;

struct StaticInstance {
  uint32_t instance = 0;
  WorldMesh world;
  double weightedArea = 0.0;  // m², area × lightmapScale²
  std::vector<Chart> charts;  // generated, in metres (texelSize 1); empty when uv1 is used
};

WorldMesh worldMeshOf(const Scene& scene, const Instance& instance) {
  const Mesh& mesh = scene.meshes.at(instance.mesh);
  WorldMesh world;
  world.indices = mesh.indices;
  world.cutEdges = mesh.cutEdges;
  world.positions.reserve(mesh.positions.size());
  for (const glm::vec3& p : mesh.positions)
    world.positions.emplace_back(instance.transform * glm::vec4(p, 1.0f));
  return world;
}

// The charts of one instance, flattened in metres and turned to their smallest rectangle.
// Charts under kSmallChartTexels texels at `texelSize` may merge across folds (chart_merge.h);
// charts under one texel that lie close and face one way are bundled (chart_bundle.h).
std::vector<Chart> generateCharts(uint32_t instance, const WorldMesh& world, float texelSize) {
  const TriangleGroups groups = segmentCharts(world, SegmentSettings{});
  // Each group flattened on its own (in parallel; the result does not depend on the order).
  std::vector<FlatGroup> flat(groups.charts.size());
  tbb::parallel_for(std::size_t{0}, flat.size(), [&](std::size_t g) {
    flat[g] = {groups.charts[g], flattenChart(world, groups.charts[g], 1.0f)};
  });
  const double smallArea = kSmallChartTexels * static_cast<double>(texelSize) * texelSize;
  flat = mergeSmallCharts(world, std::move(flat), groups.contacts, {smallArea, texelSize});
  std::vector<Chart> charts;
  for (FlatGroup& group : flat) {
    if (!group.flat.cornerUv.empty()) {
      orientChart(group.flat.cornerUv);
      charts.push_back(
          {instance, group.triangles, std::move(group.flat.cornerUv), group.flat.source});
      continue;
    }
    // No flattening of the whole region is free of folds: one chart per triangle.
    for (const uint32_t t : group.triangles) {
      FlatChart single = flattenPlanar(world, {t}, 1.0f);
      orientChart(single.cornerUv);
      charts.push_back({instance, {t}, std::move(single.cornerUv), ChartSource::Planar});
    }
  }
  if (!groups.degenerate.empty())
    charts.push_back({instance, groups.degenerate,
                      std::vector<glm::vec2>(3 * groups.degenerate.size(), glm::vec2(0.5f)),
                      ChartSource::Degenerate});
  return bundleSubTexelCharts(world, std::move(charts), texelSize);
}

// generateCharts for every instance of `statics` whose mesh has no usable uv1 at its texel and
// no charts yet, in parallel: each instance's charts depend on it alone. `uv1[i]` gets the
// check of statics[i].
template <typename TexelOf>
void generateMissingCharts(const Scene& scene, std::vector<StaticInstance>& statics,
                           const TexelOf& texelOf, const AtlasSettings& settings,
                           std::vector<Uv1Check>& uv1) {
  uv1.assign(statics.size(), Uv1Check{});
  const SilencedOpenMeshErrors silenced;  // for every thread's segmentation at once
  tbb::parallel_for(std::size_t{0}, statics.size(), [&](std::size_t i) {
    StaticInstance& s = statics[i];
    const Mesh& mesh = scene.meshes[scene.instances[s.instance].mesh];
    const float texel = texelOf(s);
    uv1[i] = checkMeshUv1(mesh, s.world, texel, settings.padding, settings.maxSize);
    if (!uv1[i].usable && s.charts.empty()) s.charts = generateCharts(s.instance, s.world, texel);
  });
}

// Scales a chart laid out in metres to texel units and returns its extent in whole texels.
glm::ivec2 toTexels(Chart& chart, float texelSize) {
  if (chart.source == ChartSource::Degenerate) return {1, 1};
  glm::vec2 hi(0.0f);
  for (glm::vec2& p : chart.cornerUv) {
    p /= texelSize;
    hi = glm::max(hi, p);
  }
  const glm::ivec2 cells(std::max(1.0f, std::ceil(hi.x - kExtentSlack)),
                         std::max(1.0f, std::ceil(hi.y - kExtentSlack)));
  // Pull an overhang within the slack back inside the cells.
  const float fit = std::min({1.0f, static_cast<float>(cells.x) / std::max(hi.x, 1e-30f),
                              static_cast<float>(cells.y) / std::max(hi.y, 1e-30f)});
  if (fit < 1.0f)
    for (glm::vec2& p : chart.cornerUv) p *= fit;
  return cells;
}

// Share of an instance's surface (m², by its triangles' areas) that its lightmap resolves and
// its triangle corners do not: triangles of at least kCoarseTriangleTexels texels² in charts at
// least kResolvedChartTexels texels across both ways, at `texelSize` metres a texel.
double resolvedShare(const std::vector<Chart>& charts, const WorldMesh& world, float texelSize) {
  double resolved = 0.0, all = 0.0;
  const double texel2 = static_cast<double>(texelSize) * texelSize;
  const float side = static_cast<float>(kResolvedChartTexels) * texelSize;
  for (const Chart& chart : charts) {
    // Charts are laid out in metres from the origin (toTexels scales them later).
    glm::vec2 hi(0.0f);
    for (const glm::vec2 p : chart.cornerUv) hi = glm::max(hi, p);
    const bool wide = chart.source != ChartSource::Degenerate && hi.x >= side && hi.y >= side;
    for (const uint32_t t : chart.triangles) {
      const double a = world.area(t);  // m²
      if (!std::isfinite(a)) continue;
      all += a;
      if (wide && a >= kCoarseTriangleTexels * texel2) resolved += a;
    }
  }
  return all > 0.0 ? resolved / all : 0.0;
}

// Share of the texels an instance's charts take (each chart's touched texels grown by
// padding/2, its half of the padding) that its surface fills: areaTexels / that count.
double lightmapFill(const std::vector<Chart>& charts, float texelSize, double areaTexels,
                    int padding) {
  std::size_t taken = 0;
  for (Chart chart : charts) {
    const glm::ivec2 cells = toTexels(chart, texelSize);
    taken += setTexels(dilateMask(rasteriseChart(chart.cornerUv, cells), padding / 2));
  }
  return taken > 0 ? areaTexels / static_cast<double>(taken) : 1.0;
}

// A chart's corners turned by 90° inside its cells (rigid: a rotation and a whole-texel shift),
// which become cells.y × cells.x.
std::vector<glm::vec2> turnedCorners(const std::vector<glm::vec2>& cornerUv, glm::ivec2 cells) {
  std::vector<glm::vec2> turned;
  turned.reserve(cornerUv.size());
  for (const glm::vec2 p : cornerUv) turned.emplace_back(static_cast<float>(cells.y) - p.y, p.x);
  return turned;
}

// Where each chart goes: its corners plus `offset` (texels) in a width × height atlas.
struct Placement {
  int width = 0, height = 0;
  std::vector<glm::ivec2> offset;
};

// The smaller of the two packings: rectangles (chart_pack.h) and texel masks (mask_pack.h).
// Charts the mask packing turns get their turned corners. Nothing when neither fits.
std::optional<Placement> placeCharts(std::vector<Chart>& charts,
                                     const std::vector<glm::ivec2>& cells, int padding,
                                     int maxSize) {
  // Each chart's mask and rectangle covers at least about its triangles' area in texels (the
  // triangles do not overlap; the rasteriser's shrunk squares lose only slivers): when that sum
  // is over twice the atlas, neither packing fits, so the texel sizes the coarsening loop is
  // bound to leave cost no mask. Twice: a safe margin for the slivers; the result is unchanged.
  double chartTexels = 0.0;
  for (const Chart& chart : charts)
    for (std::size_t k = 0; k + 2 < chart.cornerUv.size(); k += 3)
      chartTexels +=
          std::abs(signedArea(chart.cornerUv[k], chart.cornerUv[k + 1], chart.cornerUv[k + 2]));
  if (chartTexels > 2.0 * static_cast<double>(maxSize) * maxSize) return std::nullopt;
  std::vector<glm::ivec2> rects;
  for (const glm::ivec2 c : cells) rects.push_back(c + padding);
  const std::optional<Packing> byRect = packRectangles(rects, maxSize);
  // Each chart's masks turned by 0°, 90°, 180° and 270° (the charts in parallel).
  std::vector<std::vector<ChartMask>> turns(charts.size());
  tbb::parallel_for(std::size_t{0}, charts.size(), [&](std::size_t c) {
    std::vector<glm::vec2> corners = charts[c].cornerUv;
    glm::ivec2 size = cells[c];
    for (int k = 0; k < 4; ++k) {
      turns[c].push_back(rasteriseChart(corners, size));
      corners = turnedCorners(corners, size);
      size = {size.y, size.x};
    }
  });
  const std::optional<MaskPacking> byMask = packMasks(turns, padding, maxSize);
  const auto area = [](int w, int h) { return static_cast<int64_t>(w) * h; };
  if (byMask &&
      (!byRect || area(byMask->width, byMask->height) < area(byRect->width, byRect->height))) {
    for (std::size_t c = 0; c < charts.size(); ++c) {
      glm::ivec2 size = cells[c];
      for (int k = 0; k < byMask->turn[c]; ++k) {
        charts[c].cornerUv = turnedCorners(charts[c].cornerUv, size);
        size = {size.y, size.x};
      }
    }
    return Placement{byMask->width, byMask->height, byMask->origin};
  }
  if (!byRect) return std::nullopt;
  // padding/2 texels before each chart, the rest after it.
  Placement placement{byRect->width, byRect->height, byRect->origin};
  for (glm::ivec2& o : placement.offset) o += padding / 2;
  return placement;
}

}  // namespace

Atlas buildAtlas(const Scene& scene, const AtlasSettings& settings) {
  if (settings.padding < 0) throw std::invalid_argument("atlas padding must be ≥ 0 texels");
  if (settings.texelSize < 0.0f || !std::isfinite(settings.texelSize))
    throw std::invalid_argument("atlas texel size must be a positive number of metres (or 0)");
  if (settings.texelBudget < 0) throw std::invalid_argument("atlas texel budget must be ≥ 1 texel");
  if (settings.maxTexels < 1) throw std::invalid_argument("atlas texel cap must be ≥ 1 texel");
  if (settings.maxSize < 1) throw std::invalid_argument("atlas maximum size must be ≥ 1 texel");

  Atlas atlas;
  atlas.layout.padding = settings.padding;
  std::vector<StaticInstance> statics;
  double lightmappedArea = 0.0, weightedArea = 0.0;  // m²
  for (uint32_t i = 0; i < scene.instances.size(); ++i) {
    const Instance& instance = scene.instances[i];
    if (instance.mobility != Mobility::Static) continue;
    if (instance.lightmapScale == 0.0f) {  // asked for no lightmap
      atlas.vplLitInstances.push_back(i);
      continue;
    }
    StaticInstance s{i, worldMeshOf(scene, instance), 0.0, {}};
    if (s.world.triangleCount() == 0) continue;
    double area = 0.0;
    for (std::size_t t = 0; t < s.world.triangleCount(); ++t)
      if (const double a = s.world.area(t); std::isfinite(a)) area += a;
    lightmappedArea += area;
    const double scale = instance.lightmapScale;
    s.weightedArea = area * scale * scale;
    weightedArea += s.weightedArea;
    statics.push_back(std::move(s));
  }
  // Every static instance's surface, those left to probes too: the VPL clamp's A.
  atlas.staticArea = staticSurfaceArea(scene);
  atlas.weightedArea = weightedArea;
  if (statics.empty() || !(lightmappedArea > 0.0)) return atlas;

  const TexelDensity density = chooseTexelDensity(
      weightedArea, {settings.texelSize, settings.texelBudget, settings.maxTexels});
  float texelSize = density.texelSize;
  atlas.texelRule = density.rule;
  if (!density.note.empty()) atlas.notes.push_back(density.note);
  // Instances too small for a lightmap of their own take their baked light from probes.
  std::size_t tooSmall = 0;
  std::erase_if(statics, [&](const StaticInstance& s) {
    const double texels =
        s.weightedArea / (static_cast<double>(density.texelSize) * density.texelSize);
    if (texels >= kMinLightmapTexels) return false;
    atlas.vplLitInstances.push_back(s.instance);
    ++tooSmall;
    return true;
  });
  std::sort(atlas.vplLitInstances.begin(), atlas.vplLitInstances.end());
  if (tooSmall > 0)
    atlas.notes.push_back(std::to_string(tooSmall) + " static instances cover under " +
                          std::to_string(static_cast<int>(kMinLightmapTexels)) +
                          " texels each: they get no lightmap and take their baked light from "
                          "irradiance probes (a larger extras.bounce.lightmapScale keeps one)");
  if (statics.empty()) return atlas;
  // Instance i's texel edge: the scene's over its lightmapScale.
  const auto instanceTexel = [&](const StaticInstance& s) {
    return texelSize / scene.instances[s.instance].lightmapScale;
  };
  // Instances whose lightmap would be mostly padding around sub-texel pieces take the probes'
  // light too (kMinLightmapFill). A mesh's own uv1 is one square region: never judged.
  std::vector<std::string> sparse;
  std::vector<Uv1Check> uv1;
  if (settings.minLightmapFill > 0.0) {
    generateMissingCharts(scene, statics, instanceTexel, settings, uv1);
    // Whether each instance keeps its lightmap, on its own (in parallel): a mesh's own uv1, a
    // fill of at least minLightmapFill, or a surface mostly of large triangles on charts the
    // texels resolve (kMinResolvedShare).
    std::vector<uint8_t> keeps(statics.size(), 1);
    tbb::parallel_for(std::size_t{0}, statics.size(), [&](std::size_t k) {
      if (uv1[k].usable) return;
      const float texel = instanceTexel(statics[k]);
      const double areaTexels =
          statics[k].weightedArea / (static_cast<double>(texelSize) * texelSize);
      const bool filled = lightmapFill(statics[k].charts, texel, areaTexels, settings.padding) >=
                          settings.minLightmapFill;
      keeps[k] =
          filled || resolvedShare(statics[k].charts, statics[k].world, texel) >= kMinResolvedShare;
    });
    std::size_t i = 0;
    std::erase_if(statics, [&](StaticInstance& s) {
      if (keeps[i++]) return false;
      atlas.vplLitInstances.push_back(s.instance);
      sparse.push_back(scene.instances[s.instance].name);
      return true;
    });
  }
  std::sort(atlas.vplLitInstances.begin(), atlas.vplLitInstances.end());
  if (!sparse.empty()) {
    std::ostringstream note;
    note << sparse.size() << (sparse.size() == 1 ? " static instance (" : " static instances (");
    for (std::size_t k = 0; k < sparse.size() && k < 8; ++k)
      note << (k > 0 ? ", '" : "'") << sparse[k] << "'";
    note << (sparse.size() > 8 ? ", …) would fill" : ") would fill");
    note << " under " << settings.minLightmapFill * 100.0
         << " % of their lightmap texels (the rest padding around pieces smaller than a texel): "
            "they get no lightmap and take their baked light from irradiance probes (a larger "
            "extras.bounce.lightmapScale keeps one)";
    atlas.notes.push_back(note.str());
  }
  if (statics.empty()) return atlas;
  std::vector<std::string> uv1Notes;
  for (;;) {
    // Charts at this texel size: the mesh's own uv1 when usable, else generated ones.
    std::vector<Chart> charts;
    std::vector<glm::ivec2> cells;
    uv1Notes.clear();
    generateMissingCharts(scene, statics, instanceTexel, settings, uv1);
    for (std::size_t i = 0; i < statics.size(); ++i) {
      StaticInstance& s = statics[i];
      const Mesh& mesh = scene.meshes[scene.instances[s.instance].mesh];
      if (uv1[i].usable) {
        Chart chart{s.instance, {}, {}, ChartSource::MeshUv1};
        for (uint32_t t = 0; t < mesh.triangleCount(); ++t) chart.triangles.push_back(t);
        for (const uint32_t v : mesh.indices)
          chart.cornerUv.push_back(mesh.uv1[v] * static_cast<float>(uv1[i].side));
        charts.push_back(std::move(chart));
        cells.emplace_back(uv1[i].side, uv1[i].side);
        continue;
      }
      if (!uv1[i].reason.empty())
        uv1Notes.push_back("mesh '" + mesh.name + "' (instance '" +
                           scene.instances[s.instance].name + "'): " + uv1[i].reason +
                           ", so its lightmap UVs were generated");
      const float texel = instanceTexel(s);
      for (Chart chart : s.charts) {
        cells.push_back(toTexels(chart, texel));
        charts.push_back(std::move(chart));
      }
    }
    const std::optional<Placement> packing =
        placeCharts(charts, cells, settings.padding, settings.maxSize);
    if (!packing) {
      // Coarser texels shrink every chart, down to one texel plus its padding each; when even
      // that does not fit, no texel size will.
      const bool allMinimal = std::all_of(cells.begin(), cells.end(),
                                          [](glm::ivec2 c) { return c.x == 1 && c.y == 1; });
      if (allMinimal) {
        std::ostringstream reason;
        reason << "the " << charts.size() << " lightmap charts of " << scene.source
               << " do not fit in a " << settings.maxSize << " x " << settings.maxSize
               << " atlas even at one texel each (with " << settings.padding
               << " texels padding); raise the maximum atlas size";
        throw std::runtime_error(reason.str());
      }
      texelSize *= 1.1f;
      continue;
    }
    if (texelSize != density.texelSize) {
      std::ostringstream note;
      note << "the charts do not fit in " << settings.maxSize << "² texels at " << density.texelSize
           << " m per texel, so the texel size is " << texelSize << " m";
      atlas.notes.push_back(note.str());
    }

    // Place the charts.
    LightmapLayout& layout = atlas.layout;
    layout.width = packing->width;
    layout.height = packing->height;
    layout.texelSize = texelSize;
    layout.chartCount = static_cast<int>(charts.size());
    for (const Chart& chart : charts) {
      Atlas::ChartKinds& kinds = atlas.chartKinds;
      ++(chart.source == ChartSource::Planar      ? kinds.planar
         : chart.source == ChartSource::Conformal ? kinds.conformal
         : chart.source == ChartSource::MeshUv1   ? kinds.meshUv1
         : chart.source == ChartSource::Bundle    ? kinds.bundle
                                                  : kinds.degenerate);
    }
    const glm::vec2 size(static_cast<float>(layout.width), static_cast<float>(layout.height));
    layout.instances.resize(statics.size());
    atlas.triangleChart.resize(statics.size());
    for (std::size_t i = 0; i < statics.size(); ++i) {
      layout.instances[i].instance = statics[i].instance;
      layout.instances[i].cornerUv.assign(statics[i].world.indices.size(), glm::vec2(0.0f));
      atlas.triangleChart[i].assign(statics[i].world.triangleCount(), 0u);
    }
    std::vector<uint8_t> covered(static_cast<std::size_t>(layout.width) * layout.height, 0);
    for (std::size_t c = 0; c < charts.size(); ++c) {
      const Chart& chart = charts[c];
      const std::size_t slot = static_cast<std::size_t>(
          std::find_if(statics.begin(), statics.end(),
                       [&](const StaticInstance& s) { return s.instance == chart.instance; }) -
          statics.begin());
      const glm::vec2 offset(packing->offset[c]);
      for (std::size_t k = 0; k < chart.triangles.size(); ++k) {
        const uint32_t t = chart.triangles[k];
        atlas.triangleChart[slot][t] = static_cast<uint32_t>(c);
        glm::vec2 texel[3];
        for (int j = 0; j < 3; ++j) {
          const glm::vec2 uv = (chart.cornerUv[3 * k + j] + offset) / size;
          layout.instances[slot].cornerUv[3 * t + j] = uv;
          texel[j] = uv * size;
        }
        forEachTouchedTexel(
            texel[0], texel[1], texel[2], layout.width, layout.height,
            [&](int x, int y) { covered[static_cast<std::size_t>(y) * layout.width + x] = 1; });
      }
    }
    std::size_t coveredCount = 0;
    for (const uint8_t c : covered) coveredCount += c;
    layout.utilisation =
        static_cast<float>(static_cast<double>(coveredCount) / static_cast<double>(covered.size()));
    break;
  }
  atlas.notes.insert(atlas.notes.begin(), uv1Notes.begin(), uv1Notes.end());
  return atlas;
}

}  // namespace bounce
