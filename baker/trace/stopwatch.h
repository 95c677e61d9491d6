// Wall time in laps: each lap() returns the seconds since the previous one (or since it was
// made). The bake's phases time themselves with it (bake.json "seconds").
#pragma once

#include <chrono>

namespace bounce {

class Stopwatch {
 public:
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return s;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace bounce
