// An OpenGL 3.3 core context behind one small interface, with three backends (Filament's
// OpenGLPlatform split): OSMesa (software, tests and CI), EGL (headless, with or without a
// GPU) and GLFW (a window, see window.h). Creating a context makes it current and loads the GL
// functions for it. Offscreen contexts have no usable default framebuffer: every pass renders
// into a RenderTarget. Public headers of the GL layer use plain types only.
#pragma once

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

namespace bounce::gl {

enum class ContextBackend { OSMesa, EGL, GLFW };

const char* backendName(ContextBackend backend);  // "osmesa", "egl", "glfw"

// A context could not be created or made current; the message says which backend and why.
class ContextError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Context {
 public:
  virtual ~Context() = default;
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  virtual ContextBackend backend() const = 0;
  // Makes this context current on the calling thread (and points the GL functions at it).
  virtual void makeCurrent() = 0;

  // GL_VERSION and GL_RENDERER, e.g. "4.5 (Core Profile) Mesa 22.3.6", "llvmpipe (LLVM 15…)",
  // of the current context (make this one current first when several exist).
  std::string version() const;
  std::string renderer() const;
  // GL_SUBPIXEL_BITS of the current context: the rasterizer snaps vertices to 2^-bits of a pixel
  // (GL 3.3 asks for at least 4; llvmpipe and NVIDIA's driver have 8), so what a pixel's sample
  // sees is known to that step, not exactly at the pixel's centre.
  int subpixelBits() const;

 protected:
  Context() = default;
};

// Each throws ContextError when the backend yields no 3.3 core context.
std::unique_ptr<Context> createOSMesaContext();
std::unique_ptr<Context> createEglContext();

// An offscreen context: `backend` if given (OSMesa or EGL), else EGL when it yields a context and
// OSMesa otherwise. `eglFailure`, when given, receives why EGL was passed over (empty if not).
std::unique_ptr<Context> createOffscreenContext(std::optional<ContextBackend> backend,
                                                std::string* eglFailure = nullptr);

}  // namespace bounce::gl
