#include "render/light_culling.h"

#include "render/light_reach.h"

namespace bounce {

void LightCulling::setSettings(const LightCullingSettings& settings) {
  settings_ = settings;
  reachStale_ = true;
}

void LightCulling::update(const Camera& camera, int width, int height, const Box& sceneBox,
                          const PunctualLights& punctual, const AreaLightSet& area, int areaVersion,
                          LightTable& table) {
  if (!settings_.enabled) {
    table.setClusters({}, {});
    stats_ = {};
    return;
  }
  const float floor = settings_.irradianceFloor;
  if (reachStale_ || punctualReach_.size() != punctual.size()) {
    punctualReach_.clear();
    for (std::size_t i = 0; i < punctual.size(); ++i)
      punctualReach_.push_back(punctualReach(punctual.light(i), punctual.drawnPower(i), floor));
  }
  if (reachStale_ || areaVersion != areaVersion_) {
    areaReach_ = areaReaches(area, floor);
    areaVersion_ = areaVersion;
  }
  reachStale_ = false;
  const glm::vec2 depths = viewDepthRange(camera, sceneBox);
  grid_ = makeClusterGrid(camera, width, height, depths.x, depths.y, settings_.grid);
  LightGridLists lists = assignLights(grid_, punctualReach_, areaReach_);
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
