// OSMesa backend: Mesa's software rasterizer (llvmpipe) without any display. Requested as a 3.3
// core profile; Mesa 22 answers with 4.5 core.
#include <array>
#include <vector>

#include "gl/context.h"
#include "gl/driver_quirks.h"
#include "gl/gl_functions.h"
// glad/gl.h (through gl_functions.h) must come before osmesa.h, which would pull in GL/gl.h.
#include <GL/osmesa.h>

namespace bounce::gl {
namespace {

GLADapiproc osmesaProc(const char* name) {
  return reinterpret_cast<GLADapiproc>(OSMesaGetProcAddress(name));
}

class OSMesaContext final : public Context {
 public:
  OSMesaContext() {
    const std::array<int, 11> attributes = {OSMESA_FORMAT,
                                            OSMESA_RGBA,
                                            OSMESA_PROFILE,
                                            OSMESA_CORE_PROFILE,
                                            OSMESA_CONTEXT_MAJOR_VERSION,
                                            3,
                                            OSMESA_CONTEXT_MINOR_VERSION,
                                            3,
                                            OSMESA_DEPTH_BITS,
                                            0,
                                            0};
    context_ = OSMesaCreateContextAttribs(attributes.data(), nullptr);
    if (!context_)
      throw ContextError("osmesa: OSMesaCreateContextAttribs gave no OpenGL 3.3 core context");
    static_assert(kDriverQuirks.osmesaNeedsClientBuffer);
    try {
      makeCurrent();
    } catch (...) {
      OSMesaDestroyContext(context_);
      throw;
    }
  }
  ~OSMesaContext() override {
    forgetGlFunctions(this);
    OSMesaDestroyContext(context_);
  }

  ContextBackend backend() const override { return ContextBackend::OSMesa; }

  void makeCurrent() override {
    if (!OSMesaMakeCurrent(context_, clientBuffer_.data(), GL_UNSIGNED_BYTE, 1, 1))
      throw ContextError("osmesa: OSMesaMakeCurrent failed");
    loadGlFunctions(this, osmesaProc);
  }

 private:
  ::OSMesaContext context_ = nullptr;
  std::array<unsigned char, 4> clientBuffer_{};  // 1x1 RGBA, never drawn to
};

}  // namespace

std::unique_ptr<Context> createOSMesaContext() {
  return std::make_unique<OSMesaContext>();
}

}  // namespace bounce::gl
