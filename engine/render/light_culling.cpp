#include "render/light_culling.h"

#include "render/light_reach.h"

namespace bounce {
namespace {

bool sameReach(const LightReach& a, const LightReach& b) {
  return a.shape == b.shape && a.centre == b.centre && a.radius == b.radius && a.axis == b.axis &&
         a.cosOuter == b.cosOuter && a.sinOuter == b.sinOuter && a.box.lower == b.box.lower &&
         a.box.upper == b.box.upper;
}

bool sameReaches(const std::vector<LightReach>& a, const std::vector<LightReach>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!sameReach(a[i], b[i])) return false;
  return true;
}

}  // namespace

void LightCulling::setSettings(const LightCullingSettings& settings) {
  settings_ = settings;
  reachStale_ = true;
  builtFor_.reset();
}

void LightCulling::update(const Camera& camera, int width, int height, const Box& sceneBox,
                          const PunctualLights& punctual, const AreaLightSet& area, int areaVersion,
                          LightTable& table, std::span<const uint32_t> punctualOrder) {
  if (!settings_.enabled) {
    table.setClusters({}, {});
    stats_ = {};
    builtFor_.reset();
    return;
  }
  const float floor = settings_.irradianceFloor;
  // Every frame (a few per light): a light moved or dimmed by setLight changes its reach.
  punctualReach_.clear();
  for (std::size_t i = 0; i < punctual.size(); ++i)
    punctualReach_.push_back(punctualReach(punctual.light(i), punctual.drawnPower(i), floor));
  if (reachStale_ || areaVersion != areaVersion_) {
    areaReach_ = areaReaches(area, floor);
    areaVersion_ = areaVersion;
  }
  reachStale_ = false;
  BuiltFor key{camera.cameraToWorld,
               glm::vec4(camera.yfov, camera.aspect, camera.znear, camera.zfar),
               glm::ivec2(width, height),
               sceneBox,
               {},
               {},
               {punctualOrder.begin(), punctualOrder.end()}};
  const bool still =
      builtFor_ && builtFor_->cameraToWorld == key.cameraToWorld && builtFor_->lens == key.lens &&
      builtFor_->size == key.size && builtFor_->sceneBox.lower == sceneBox.lower &&
      builtFor_->sceneBox.upper == sceneBox.upper &&
      sameReaches(builtFor_->punctual, punctualReach_) &&
      sameReaches(builtFor_->area, areaReach_) && builtFor_->punctualOrder == key.punctualOrder;
  // A still view: the light table keeps the lists it holds.
  if (still) return;
  key.punctual = punctualReach_;
  key.area = areaReach_;
  builtFor_ = std::move(key);
  ++gridBuilds_;
  const glm::vec2 depths = viewDepthRange(camera, sceneBox);
  grid_ = makeClusterGrid(camera, width, height, depths.x, depths.y, settings_.grid);
  LightGridLists lists = assignLights(grid_, punctualReach_, areaReach_, builtFor_->punctualOrder);
  stats_ = {grid_.count(), lists.punctualEntries, lists.areaEntries, lists.maxPunctual,
            lists.maxArea};
  table.setClusters(std::move(lists.headers), std::move(lists.entries));
}

void LightCulling::bind(gl::Program& program) const {
  program.set("uLightGridEnabled", settings_.enabled ? 1 : 0);
  program.set("uClusterTilePixels", grid_.tilePixels);
  program.set("uClusterCounts", glm::ivec3(grid_.tilesX, grid_.tilesY, grid_.slices));
  program.set("uClusterSlice", grid_.sliceScaleBias());
  // View depth d = −z_view = dot(−(third row of the view matrix), (p, 1)).
  const glm::mat4& v = grid_.view;
  program.set("uViewDepthRow", -glm::vec4(v[0][2], v[1][2], v[2][2], v[3][2]));
}

}  // namespace bounce
