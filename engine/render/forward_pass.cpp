#include "render/forward_pass.h"

#include "gl/draw_state.h"
#include "gl/render_target.h"
#include "render/gpu_scene.h"
#include "render/light_culling.h"
#include "render/light_table.h"
#include "render/lightmap_pass.h"
#include "render/probe_pass.h"
#include "render/shader_constants.h"
#include "render/shadow_pass.h"
#include "render/texture_units.h"
#include "render/vpl_pass.h"
#include "render/vpl_vertex_light.h"

namespace bounce {

ForwardPass::ForwardPass(const std::filesystem::path& shaderDir)
    : program_(shaderDir / "forward.vert", shaderDir / "forward.geom", shaderDir / "forward.frag",
               shaderConstants()) {}

void ForwardPass::draw(const GpuScene& scene, const LightTable& lights, const LightCulling& culling,
                       const ShadowPass& shadows, const LightmapPass& lightmap,
                       const ProbePass& probes, const VplPass& vpls,
                       const VplVertexLight& vplVertexLight, RenderMode mode,
                       const glm::mat4& viewProjection, gl::RenderTarget& target) {
  target.bind();
  gl::clear(glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  gl::setDepthTest(true);

  program_.set("uViewProjection", viewProjection);
  lights.bind(program_);
  culling.bind(program_);
  shadows.bind(program_);
  program_.set("uEmitterCount", scene.emitterCount());
  program_.set("uAreaLightCount", scene.areaLightCount());
  program_.set("uEmitters", TextureUnit::kEmitters);
  program_.set("uAlbedoTexture", TextureUnit::kAlbedo);
  scene.bindEmitters(TextureUnit::kEmitters);
  lightmap.bind(program_, mode);
  probes.bind(program_);
  vpls.bind(program_);
  vplVertexLight.bind(program_);

  const std::span<const GpuInstance> instances = scene.instances();
  for (std::size_t i = 0; i < instances.size(); ++i) {
    const GpuInstance& instance = instances[i];
    lightmap.setInstance(program_, i);
    probes.setInstance(program_, i);
    vpls.setInstance(program_, scene, i, lightmap.lightmapped(i) || probes.probeLit(i));
    vplVertexLight.setInstance(program_, scene, i);
    const GpuMaterial& material = scene.bindMaterial(instance, program_, TextureUnit::kAlbedo);
    // glTF: a single-sided surface is invisible from behind (and emits only forwards).
    gl::setBackFaceCulling(!material.doubleSided, instance.mirrored);
    scene.draw(instance, program_);
  }
  gl::setBackFaceCulling(false);
  target.resolve();  // multisampled: each pixel's mean radiance, before any tone mapping
  gl::checkErrors("forward pass");
}

}  // namespace bounce
