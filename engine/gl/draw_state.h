// The fixed-function state a pass sets before drawing, as plain calls.
#pragma once

#include <glm/glm.hpp>

namespace bounce::gl {

// Clears the bound framebuffer's colour to `color` and depth to the far plane.
void clear(glm::vec4 color);
// Clears the bound framebuffer's depth (only) to the far plane.
void clearDepth();
// Depth test (less) and depth writes on or off.
void setDepthTest(bool enabled);
// Culls back faces when true. Front faces are counter-clockwise on screen, or clockwise when
// `mirrored` (an instance whose transform has a negative determinant flips its winding).
void setBackFaceCulling(bool enabled, bool mirrored = false);
// Draws one triangle covering the viewport; the vertex shader makes its corners from
// gl_VertexID (no attributes), see shaders/fullscreen.vert.
void drawFullscreenTriangle();
// Blocks until the GPU has finished every command issued so far.
void finish();
// Throws std::logic_error "<what>: GL_INVALID_…" if a GL call since the last check failed: a bug
// in bounce (bad state or arguments), never a user error.
void checkErrors(const char* what);

}  // namespace bounce::gl
