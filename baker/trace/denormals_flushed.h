// Flush-to-zero and denormals-are-zero for the scope of one work item (as Embree asks), the
// previous mode restored after: every item, whichever thread runs it, computes with the same
// float mode, so results do not depend on the schedule.
#pragma once

#if defined(__SSE__)
#include <pmmintrin.h>
#include <xmmintrin.h>
#endif

namespace bounce {

class DenormalsFlushed {
 public:
#if defined(__SSE__)
  DenormalsFlushed() : saved_(_mm_getcsr()) {
    _mm_setcsr(saved_ | 0x8040u);
  }
  ~DenormalsFlushed() {
    _mm_setcsr(saved_);
  }
#else
  DenormalsFlushed() = default;
#endif
  DenormalsFlushed(const DenormalsFlushed&) = delete;
  DenormalsFlushed& operator=(const DenormalsFlushed&) = delete;

#if defined(__SSE__)
 private:
  unsigned saved_;
#endif
};

}  // namespace bounce
