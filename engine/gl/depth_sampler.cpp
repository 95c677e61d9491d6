#include "gl/depth_sampler.h"

#include "gl/gl_functions.h"

namespace bounce::gl {

DepthValueSampler::DepthValueSampler() {
  glGenSamplers(1, &id_);
  glSamplerParameteri(id_, GL_TEXTURE_COMPARE_MODE, GL_NONE);
  glSamplerParameteri(id_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glSamplerParameteri(id_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(id_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(id_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(id_, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
}

DepthValueSampler::~DepthValueSampler() {
  if (id_) glDeleteSamplers(1, &id_);
}

void DepthValueSampler::bind(int unit) const {
  // Cube maps filter across face edges (core since 3.2; off by default): without it a bilinear
  // read near an edge clamps to one face and a vertical seam of wrong depths shows on walls.
  glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  glBindSampler(static_cast<GLuint>(unit), id_);
}

}  // namespace bounce::gl
