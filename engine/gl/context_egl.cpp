// EGL headless backend: no window, no X. The display comes from Mesa's surfaceless platform or,
// failing that, the first EGL device; the context is made current without a surface and renders
// into FBOs only (EGL_KHR_surfaceless_context).
#include <string>
#include <vector>

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include "gl/context.h"
#include "gl/driver_quirks.h"
#include "gl/gl_functions.h"

namespace bounce::gl {
namespace {

GLADapiproc eglProc(const char* name) {
  return reinterpret_cast<GLADapiproc>(eglGetProcAddress(name));
}

std::string eglErrorName() {
  switch (eglGetError()) {
    case EGL_NOT_INITIALIZED:
      return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
      return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
      return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
      return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
      return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
      return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY:
      return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
      return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER:
      return "EGL_BAD_PARAMETER";
    default:
      return "EGL error";
  }
}

bool hasExtension(const char* list, const std::string& name) {
  if (!list) return false;
  const std::string all = std::string(" ") + list + " ";
  return all.find(" " + name + " ") != std::string::npos;
}

// Returns an initialized display, or EGL_NO_DISPLAY with `why` filled in.
EGLDisplay openHeadlessDisplay(std::string& why) {
  static_assert(kDriverQuirks.eglDefaultDisplayNeedsX);
  const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!getPlatformDisplay) {
    why = "eglGetPlatformDisplayEXT is missing (no EGL_EXT_platform_base)";
    return EGL_NO_DISPLAY;
  }
  EGLint major = 0, minor = 0;
  if (hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
    EGLDisplay display =
        getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display != EGL_NO_DISPLAY && eglInitialize(display, &major, &minor)) return display;
    why = "the surfaceless platform failed (" + eglErrorName() + ")";
  }
  auto queryDevices =
      reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  if (hasExtension(clientExtensions, "EGL_EXT_platform_device") && queryDevices) {
    EGLDeviceEXT devices[8];
    EGLint count = 0;
    if (queryDevices(8, devices, &count) && count > 0) {
      for (EGLint i = 0; i < count; ++i) {
        EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        if (display != EGL_NO_DISPLAY && eglInitialize(display, &major, &minor)) return display;
      }
      why += (why.empty() ? "" : "; ") + std::string("no EGL device initializes");
    } else {
      why += (why.empty() ? "" : "; ") + std::string("no EGL devices");
    }
  }
  if (why.empty()) why = "neither EGL_MESA_platform_surfaceless nor EGL_EXT_platform_device";
  return EGL_NO_DISPLAY;
}

class EglContext final : public Context {
 public:
  EglContext() {
    std::string why;
    display_ = openHeadlessDisplay(why);
    if (display_ == EGL_NO_DISPLAY) throw ContextError("egl: no headless display: " + why);
    if (!hasExtension(eglQueryString(display_, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context"))
      throw ContextError("egl: the display lacks EGL_KHR_surfaceless_context");
    if (!eglBindAPI(EGL_OPENGL_API))
      throw ContextError("egl: eglBindAPI(EGL_OPENGL_API) failed (" + eglErrorName() + ")");
    // Surfaceless configs offer pbuffers, not windows (eglChooseConfig defaults to windows).
    const EGLint configAttributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE,
                                       EGL_PBUFFER_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configCount = 0;
    if (!eglChooseConfig(display_, configAttributes, &config, 1, &configCount) || configCount < 1)
      throw ContextError("egl: no config renders desktop OpenGL (" + eglErrorName() + ")");
    const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                        3,
                                        EGL_CONTEXT_MINOR_VERSION,
                                        3,
                                        EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                        EGL_NONE};
    context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, contextAttributes);
    if (context_ == EGL_NO_CONTEXT)
      throw ContextError("egl: no OpenGL 3.3 core context (" + eglErrorName() + ")");
    try {
      makeCurrent();
    } catch (...) {
      eglDestroyContext(display_, context_);
      throw;
    }
  }
  // The display is process-wide (EGL returns the same handle to every caller) and is left
  // initialized: terminating it would pull the driver from under other contexts.
  ~EglContext() override {
    forgetGlFunctions(this);
    if (eglGetCurrentContext() == context_)
      eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
  }

  ContextBackend backend() const override { return ContextBackend::EGL; }

  void makeCurrent() override {
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
      throw ContextError("egl: eglMakeCurrent without a surface failed (" + eglErrorName() + ")");
    loadGlFunctions(this, eglProc);
  }

 private:
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<Context> createEglContext() {
  return std::make_unique<EglContext>();
}

}  // namespace bounce::gl
