#include "render/light_table.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "render/texture_units.h"

namespace bounce {

void LightTable::setPunctual(std::vector<glm::vec4> texels) {
  punctual_ = std::move(texels);
  dirty_ = true;
}

void LightTable::setVpls(std::vector<glm::vec4> lightTexels, std::vector<glm::vec4> cutTexels) {
  vplLights_ = std::move(lightTexels);
  vplCuts_ = std::move(cutTexels);
  dirty_ = true;
}

void LightTable::setClusters(std::vector<glm::vec4> headers, std::vector<glm::vec4> entries) {
  // A still view gives the same lists: keep the uploaded table (it may hold many VPLs).
  if (headers == clusters_ && entries == clusterEntries_) return;
  clusters_ = std::move(headers);
  clusterEntries_ = std::move(entries);
  dirty_ = true;
}

void LightTable::update() {
  if (!dirty_ && buffer_) return;
  std::vector<glm::vec4> all;
  all.reserve(punctual_.size() + vplLights_.size() + vplCuts_.size() + clusters_.size() +
              clusterEntries_.size());
  for (const std::vector<glm::vec4>* section :
       {&punctual_, &vplLights_, &vplCuts_, &clusters_, &clusterEntries_})
    all.insert(all.end(), section->begin(), section->end());
  const std::size_t limit = std::min(kMaxLightTableTexels, gl::TextureBuffer::maxTexels());
  if (all.size() > limit)
    throw std::runtime_error("light table of " + std::to_string(all.size()) + " texels (" +
                             std::to_string(punctualCount()) + " punctual lights, " +
                             std::to_string(vplLights_.size() / 3) + " VPL lights, " +
                             std::to_string(vplCuts_.size()) + " cut texels, " +
                             std::to_string(clusters_.size() + clusterEntries_.size()) +
                             " light-grid texels) exceeds " + std::to_string(limit) +
                             " (GL_MAX_TEXTURE_BUFFER_SIZE, and 2^24 for exact float indices)");
  buffer_.reset();
  buffer_.emplace(std::span<const glm::vec4>(all));
  dirty_ = false;
}

void LightTable::bind(gl::Program& program) const {
  if (!buffer_) throw std::logic_error("LightTable::bind before update");
  program.set("uLightTable", TextureUnit::kLightTable);
  program.set("uPunctualCount", static_cast<int>(punctualCount()));
  program.set("uVplLightsFirst", static_cast<int>(punctual_.size()));
  const std::size_t clustersFirst = punctual_.size() + vplLights_.size() + vplCuts_.size();
  program.set("uVplCutsFirst", static_cast<int>(punctual_.size() + vplLights_.size()));
  program.set("uClustersFirst", static_cast<int>(clustersFirst));
  program.set("uClusterEntriesFirst", static_cast<int>(clustersFirst + clusters_.size()));
  buffer_->bind(TextureUnit::kLightTable);
}

}  // namespace bounce
