#include "gl/gl_functions.h"

#include <string>

#include "gl/context.h"
#include "gl/driver_quirks.h"

#ifdef __SANITIZE_ADDRESS__
#include <dlfcn.h>
#include <link.h>

#include <cstring>
#endif

namespace bounce::gl {
namespace {
// glad keeps one process-wide function table; it belongs to the context loaded last.
const Context* loadedFor = nullptr;
}  // namespace

#ifdef __SANITIZE_ADDRESS__
// Re-opens every loaded GL driver library with RTLD_NODELETE so that it stays mapped until exit.
void keepDriversLoaded() {
  static_assert(kDriverQuirks.driversUnloadBeforeLeakCheck);
  dl_iterate_phdr(
      [](dl_phdr_info* info, std::size_t, void*) {
        const char* name = info->dlpi_name;
        if (name && (std::strstr(name, "_dri.so") || std::strstr(name, "libGLX_mesa") ||
                     std::strstr(name, "libEGL_mesa") || std::strstr(name, "libgallium")))
          dlopen(name, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
        return 0;
      },
      nullptr);
}
#else
void keepDriversLoaded() {}
#endif

void loadGlFunctions(const Context* context, GLADloadfunc load) {
  if (context == loadedFor) return;
  keepDriversLoaded();
  const int version = gladLoadGL(load);
  if (version == 0) throw ContextError("cannot load the OpenGL functions of the new context");
  if (GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < 33)
    throw ContextError("the context offers OpenGL " + std::to_string(GLAD_VERSION_MAJOR(version)) +
                       "." + std::to_string(GLAD_VERSION_MINOR(version)) + ", bounce needs 3.3");
  loadedFor = context;
}

void forgetGlFunctions(const Context* context) {
  if (context == loadedFor) loadedFor = nullptr;
}

}  // namespace bounce::gl

// LeakSanitizer suppressions for the GL drivers (debug preset, -fsanitize=address): Mesa's
// OSMesa keeps ~0.5 KB per process after its context is destroyed, and the EGL/DRI driver's
// allocations show as leaks once it is unloaded at exit. They are the drivers', not bounce's.
// LSan calls this hook when it is linked in; it lives here because every backend links this
// file (a file of its own would be dropped from the static library).
extern "C" const char* __lsan_default_suppressions();
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libOSMesa.so\n"
         "leak:libEGL_mesa.so\n"
         "leak:libgallium\n"
         "leak:swrast_dri.so\n"
         "leak:libglapi.so\n"
         "leak:libGLX_mesa.so\n";
}
