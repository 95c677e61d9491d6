#include "frame_time.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <vector>

#include "gl/draw_state.h"

namespace bounce::test {
namespace {

double processCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

}  // namespace

FrameTime frameMilliseconds(ForwardRenderer& renderer, const Camera& camera,
                            gl::RenderTarget& target, int frames) {
  for (int i = 0; i < 2; ++i) renderer.render(camera, target);
  gl::finish();
  std::vector<double> ms;
  const double cpuStart = processCpuMs();
  for (int i = 0; i < frames; ++i) {
    const auto start = std::chrono::steady_clock::now();
    renderer.render(camera, target);
    gl::finish();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                     .count());
  }
  const double cpu = (processCpuMs() - cpuStart) / frames;
  std::sort(ms.begin(), ms.end());
  return {ms[ms.size() / 2], cpu};
}

}  // namespace bounce::test
