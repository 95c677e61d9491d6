#include "gl/gl_functions.h"

#include <string>

#include "gl/context.h"

namespace bounce::gl {
namespace {
// glad keeps one process-wide function table; it belongs to the context loaded last.
const Context* loadedFor = nullptr;
}  // namespace

void loadGlFunctions(const Context* context, GLADloadfunc load) {
  if (context == loadedFor) return;
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
