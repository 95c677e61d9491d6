#include "gl/gpu_timer.h"

#include "gl/gl_functions.h"

namespace bounce::gl {

GpuTimer::GpuTimer() {
  glGenQueries(kInFlight, queries_.data());
}

GpuTimer::~GpuTimer() {
  glDeleteQueries(kInFlight, queries_.data());
}

void GpuTimer::begin() {
  // Collect every finished span first; if the slot to reuse is still running, wait for it (it
  // is kInFlight frames old, so the GPU has long finished it on any real driver).
  for (int i = 0; i < kInFlight; ++i) {
    const int slot = (next_ + i) % kInFlight;
    if (!pending_[slot]) continue;
    GLint available = 0;
    glGetQueryObjectiv(queries_[slot], GL_QUERY_RESULT_AVAILABLE, &available);
    if (!available && slot != next_) continue;
    GLuint64 nanoseconds = 0;
    glGetQueryObjectui64v(queries_[slot], GL_QUERY_RESULT, &nanoseconds);
    pending_[slot] = false;
    last_ = static_cast<double>(nanoseconds) * 1e-6;
  }
  glBeginQuery(GL_TIME_ELAPSED, queries_[next_]);
}

void GpuTimer::end() {
  glEndQuery(GL_TIME_ELAPSED);
  pending_[next_] = true;
  next_ = (next_ + 1) % kInFlight;
}

}  // namespace bounce::gl
