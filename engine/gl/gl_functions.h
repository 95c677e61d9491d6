// Private to the GL layer: the generated glad loader and the one place GL entry points are
// (re)loaded when a context becomes current. Never include from a public header.
#pragma once

#include <glad/gl.h>

namespace bounce::gl {

class Context;

// Points glad's function table at `context`'s driver (a no-op when it already is); throws
// ContextError when the driver gives no GL 3.3.
void loadGlFunctions(const Context* context, GLADloadfunc load);
// Called by a dying context so that a new one at the same address reloads.
void forgetGlFunctions(const Context* context);

}  // namespace bounce::gl
