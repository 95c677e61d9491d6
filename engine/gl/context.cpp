#include "gl/context.h"

#include "gl/gl_functions.h"

namespace bounce::gl {
namespace {
std::string glString(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "";
}
}  // namespace

const char* backendName(ContextBackend backend) {
  switch (backend) {
    case ContextBackend::OSMesa:
      return "osmesa";
    case ContextBackend::EGL:
      return "egl";
    case ContextBackend::GLFW:
      return "glfw";
  }
  return "?";
}

std::string Context::version() const {
  return glString(GL_VERSION);
}
std::string Context::renderer() const {
  return glString(GL_RENDERER);
}
int Context::subpixelBits() const {
  GLint bits = 0;
  glGetIntegerv(GL_SUBPIXEL_BITS, &bits);
  return bits;
}

std::unique_ptr<Context> createOffscreenContext(std::optional<ContextBackend> backend,
                                                std::string* eglFailure) {
  if (eglFailure) eglFailure->clear();
  if (backend == ContextBackend::OSMesa) return createOSMesaContext();
  if (backend == ContextBackend::EGL) return createEglContext();
  if (backend == ContextBackend::GLFW)
    throw ContextError("glfw is a window backend, not an offscreen one (use osmesa or egl)");
  try {
    return createEglContext();
  } catch (const ContextError& e) {
    if (eglFailure) *eglFailure = e.what();
  }
  return createOSMesaContext();
}

}  // namespace bounce::gl
