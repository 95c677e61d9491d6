// bounce-bake's progress line and its Ctrl-C: shared by the bake and the merge.
#pragma once

#include <csignal>
#include <cstdio>

#include "trace/stage_progress.h"

namespace bounce {

// Set by SIGINT/SIGTERM (listenForInterrupt): the bake stops at its next check.
inline volatile std::sig_atomic_t interrupted = 0;
extern "C" inline void onBakeInterrupt(int) {
  interrupted = 1;
}
inline void listenForInterrupt() {
  std::signal(SIGINT, onBakeInterrupt);
  std::signal(SIGTERM, onBakeInterrupt);
}

// The progress line on stderr ("[4/8] irradiance 45.1%  2.31 Msamples/s  ETA 12 s"), rewritten
// in place; cancels when interrupted.
class ProgressLineObserver final : public BakeObserver {
 public:
  explicit ProgressLineObserver(bool draw) : draw_(draw) {}
  bool onProgress(const BakeProgress& p) override {
    if (draw_) {
      const double percent =
          p.total > 0 ? 100.0 * static_cast<double>(p.done) / static_cast<double>(p.total) : 100.0;
      std::fprintf(stderr, "\rbounce-bake: [%d/%d] %-24s %5.1f%%", p.stage, p.stages,
                   p.name.c_str(), percent);
      if (p.samplesPerSecond > 0.0)
        std::fprintf(stderr, "  %.2f Msamples/s", p.samplesPerSecond * 1e-6);
      std::fprintf(stderr, p.finished ? "  %.1f s        \n" : "  ETA %.0f s        ",
                   p.finished ? p.seconds : p.etaSeconds);
      std::fflush(stderr);
    }
    return interrupted == 0;
  }

 private:
  bool draw_;
};

}  // namespace bounce
