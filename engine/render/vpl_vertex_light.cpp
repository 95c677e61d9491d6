#include "render/vpl_vertex_light.h"

#include <algorithm>
#include <array>
#include <map>
#include <span>

#include <glm/glm.hpp>

#include "gl/draw_state.h"
#include "gl/texture.h"
#include "render/gpu_scene.h"
#include "render/light_table.h"
#include "render/shader_constants.h"
#include "render/texture_units.h"
#include "render/vpl_pass.h"

namespace bounce {

namespace {

// The mesh's distinct (position, normal) pairs, 2 texels each, and per corner of its
// de-indexed draw (gl/mesh_buffer.h: corner k is indices[k]) the pair it is: a mesh written
// with 3 vertices per triangle (the Cornell sphere: 6,624 for 1,106 points) is gathered once
// per point.
struct WeldedVertices {
  std::vector<glm::vec4> texels;
  std::vector<glm::uvec2> corners;
};

WeldedVertices weldedVertices(const Mesh& mesh) {
  WeldedVertices w;
  std::map<std::array<float, 6>, uint32_t> ids;
  std::vector<uint32_t> idOf(mesh.positions.size());
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const glm::vec3 p = mesh.positions[v];
    const glm::vec3 n = v < mesh.normals.size() ? mesh.normals[v] : glm::vec3(0.0f);
    const auto [it, added] =
        ids.try_emplace({p.x, p.y, p.z, n.x, n.y, n.z}, static_cast<uint32_t>(ids.size()));
    if (added) {
      w.texels.emplace_back(p, 0.0f);
      w.texels.emplace_back(n, 0.0f);
    }
    idOf[v] = it->second;
  }
  w.corners.reserve(mesh.indices.size());
  for (const uint32_t v : mesh.indices) w.corners.emplace_back(idOf.at(v), 0u);
  return w;
}

int rowsFor(int vertices) {
  return std::max(1, (vertices + kVplVertexLightWidth - 1) / kVplVertexLightWidth);
}

}  // namespace

VplVertexLight::VplVertexLight(const Scene& scene, const std::filesystem::path& shaderDir)
    : program_(shaderDir / "fullscreen.vert", shaderDir / "vpl_vertex_light.frag",
               shaderConstants()),
      noCorners_(std::span<const glm::uvec2>()) {
  meshes_.resize(scene.meshes.size());
  for (const Instance& instance : scene.instances) {
    if (instance.mobility != Mobility::Dynamic || instance.mesh >= scene.meshes.size() ||
        meshes_[instance.mesh])
      continue;
    const WeldedVertices welded = weldedVertices(scene.meshes[instance.mesh]);
    meshes_[instance.mesh].emplace(MeshTables{gl::TextureBuffer(welded.texels),
                                              gl::TextureBuffer(welded.corners),
                                              static_cast<int>(welded.texels.size() / 2)});
  }
  target_.emplace(kVplVertexLightWidth, 1);  // the stand-in until something is gathered
}

void VplVertexLight::clear() {
  rowOf_.clear();
  gatheredVersion_.reset();
}

void VplVertexLight::render(const GpuScene& scene, const LightTable& table, const VplPass& vpls) {
  const std::span<const GpuInstance> instances = scene.instances();
  std::vector<glm::mat4> models;
  models.reserve(instances.size());
  for (const GpuInstance& instance : instances) models.push_back(instance.model);
  if (gatheredVersion_ == vpls.version() && models == gatheredModels_) return;
  gatheredModels_ = std::move(models);
  gatheredVersion_ = vpls.version();
  rowOf_.assign(instances.size(), -1);
  if (!vpls.attached()) return;
  int rows = 0;
  for (std::size_t i = 0; i < instances.size(); ++i) {
    const GpuInstance& instance = instances[i];
    if (instance.mobility != Mobility::Dynamic || instance.mesh >= meshes_.size() ||
        !meshes_[instance.mesh])
      continue;
    rowOf_[i] = rows;
    rows += rowsFor(meshes_[instance.mesh]->vertexCount);
  }
  // Instances beyond the largest texture gather per pixel.
  const int maxRows = gl::Texture2D::maxSize();
  for (std::size_t i = 0; i < instances.size(); ++i)
    if (rowOf_[i] >= 0 && rowOf_[i] + rowsFor(meshes_[instances[i].mesh]->vertexCount) > maxRows)
      rowOf_[i] = -1;
  rows = std::min(rows, maxRows);
  if (rows == 0) return;
  ++gathers_;
  if (target_->height() < rows) {
    target_.reset();
    target_.emplace(kVplVertexLightWidth, rows);
  }
  target_->bind();
  gl::setDepthTest(false);
  table.bind(program_);
  vpls.bind(program_);
  program_.set("uVertices", TextureUnit::kVplCornerVertex);
  for (std::size_t i = 0; i < instances.size(); ++i) {
    if (rowOf_[i] < 0) continue;
    const MeshTables& mesh = *meshes_[instances[i].mesh];
    mesh.vertices.bind(TextureUnit::kVplCornerVertex);
    gl::setViewport(0, rowOf_[i], kVplVertexLightWidth, rowsFor(mesh.vertexCount));
    program_.set("uVertexCount", mesh.vertexCount);
    program_.set("uRow", rowOf_[i]);
    program_.set("uModel", instances[i].model);
    program_.set("uNormalMatrix", instances[i].normalMatrix);
    gl::drawFullscreenTriangle();
  }
  gl::checkErrors("VPL vertex light");
}

void VplVertexLight::bind(gl::Program& program) const {
  program.set("uVplVertexLight", TextureUnit::kVplVertexLight);
  program.set("uVplCornerVertex", TextureUnit::kVplCornerVertex);
  target_->color().bind(TextureUnit::kVplVertexLight);
  noCorners_.bind(TextureUnit::kVplCornerVertex);
}

void VplVertexLight::setInstance(gl::Program& program, const GpuScene& scene,
                                 std::size_t index) const {
  program.set("uHasVplVertexLight", gathered(index) ? 1 : 0);
  if (!gathered(index)) return;
  meshes_[scene.instances()[index].mesh]->corners.bind(TextureUnit::kVplCornerVertex);
  program.set("uVplVertexFirst", rowOf_[index] * kVplVertexLightWidth);
}

}  // namespace bounce
