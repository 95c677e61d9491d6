#include "gl/draw_state.h"

#include <stdexcept>
#include <string>

#include "gl/gl_functions.h"

namespace bounce::gl {

void clear(glm::vec4 color) {
  glClearColor(color.r, color.g, color.b, color.a);
  glDepthMask(GL_TRUE);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void clearDepth() {
  glDepthMask(GL_TRUE);
  glClear(GL_DEPTH_BUFFER_BIT);
}

void setDepthTest(bool enabled) {
  if (enabled) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
  } else {
    glDisable(GL_DEPTH_TEST);
  }
  glDepthMask(enabled ? GL_TRUE : GL_FALSE);
}

void setBackFaceCulling(bool enabled, bool mirrored) {
  // The winding also decides gl_FrontFacing, so it is set even without culling.
  glFrontFace(mirrored ? GL_CW : GL_CCW);
  if (enabled) {
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
  } else {
    glDisable(GL_CULL_FACE);
  }
}

void drawFullscreenTriangle() {
  // A core profile draws only with a vertex array bound, even one without attributes. One per
  // context: vertex arrays are not shared between contexts.
  GLuint vertexArray = 0;
  glGenVertexArrays(1, &vertexArray);
  glBindVertexArray(vertexArray);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glDeleteVertexArrays(1, &vertexArray);
}

void finish() {
  glFinish();
}

void checkErrors(const char* what) {
  std::string errors;
  for (GLenum error = glGetError(); error != GL_NO_ERROR; error = glGetError()) {
    switch (error) {
      case GL_INVALID_ENUM:
        errors += " GL_INVALID_ENUM";
        break;
      case GL_INVALID_VALUE:
        errors += " GL_INVALID_VALUE";
        break;
      case GL_INVALID_OPERATION:
        errors += " GL_INVALID_OPERATION";
        break;
      case GL_INVALID_FRAMEBUFFER_OPERATION:
        errors += " GL_INVALID_FRAMEBUFFER_OPERATION";
        break;
      case GL_OUT_OF_MEMORY:
        errors += " GL_OUT_OF_MEMORY";
        break;
      default:
        errors += " GL error " + std::to_string(error);
    }
    if (errors.size() > 200) break;  // a broken context can report errors forever
  }
  if (!errors.empty()) throw std::logic_error(std::string(what) + ":" + errors);
}

}  // namespace bounce::gl
