#include "gl/gpu_pass_timers.h"

#include <stdexcept>

#include "gl/gl_functions.h"

namespace bounce::gl {

GpuPassTimers::~GpuPassTimers() {
  for (const Frame& frame : inFlight_)
    for (const Query& query : frame) {
      glDeleteQueries(1, &query.start);
      glDeleteQueries(1, &query.end);
    }
  if (!spare_.empty()) glDeleteQueries(static_cast<GLsizei>(spare_.size()), spare_.data());
}

uint32_t GpuPassTimers::newQuery() {
  if (!spare_.empty()) {
    const uint32_t id = spare_.back();
    spare_.pop_back();
    return id;
  }
  GLuint id = 0;
  glGenQueries(1, &id);
  return id;
}

bool GpuPassTimers::collectOldest(bool wait) {
  Frame& oldest = inFlight_.front();
  if (!wait)
    for (const Query& query : oldest) {
      GLint available = 0;
      glGetQueryObjectiv(query.end, GL_QUERY_RESULT_AVAILABLE, &available);
      if (!available) return false;
    }
  GpuFrameTimes times;
  for (const Query& query : oldest) {
    GLuint64 start = 0, end = 0;
    glGetQueryObjectui64v(query.start, GL_QUERY_RESULT, &start);
    glGetQueryObjectui64v(query.end, GL_QUERY_RESULT, &end);
    times.passes.push_back(
        {query.name, end > start ? static_cast<double>(end - start) * 1e-6 : 0.0});
    spare_.push_back(query.start);
    spare_.push_back(query.end);
  }
  if (!times.passes.empty()) finished_.push_back(std::move(times));
  inFlight_.pop_front();
  return true;
}

void GpuPassTimers::beginFrame() {
  if (!open_.empty()) throw std::logic_error("GpuPassTimers: a frame began inside a timed pass");
  // Every frame but the one just ended may be read; the oldest must be once the ring is full.
  while (inFlight_.size() > 1 && collectOldest(inFlight_.size() >= kFramesInFlight)) {
  }
  inFlight_.emplace_back();
}

void GpuPassTimers::begin(const char* name) {
  if (inFlight_.empty()) inFlight_.emplace_back();
  const uint32_t start = newQuery();
  glQueryCounter(start, GL_TIMESTAMP);
  inFlight_.back().push_back({name, start, 0});
  open_.push_back(inFlight_.back().size() - 1);
}

void GpuPassTimers::end() {
  if (open_.empty()) throw std::logic_error("GpuPassTimers::end without begin");
  const uint32_t end = newQuery();
  glQueryCounter(end, GL_TIMESTAMP);
  inFlight_.back()[open_.back()].end = end;
  open_.pop_back();
}

void GpuPassTimers::finish() {
  while (!inFlight_.empty()) collectOldest(true);
}

std::vector<GpuFrameTimes> GpuPassTimers::takeFinished() {
  std::vector<GpuFrameTimes> frames;
  frames.swap(finished_);
  return frames;
}

}  // namespace bounce::gl
