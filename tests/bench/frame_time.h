// The forward renderer's frame time as the renderer benches measure it (bench_shadows,
// bench_vpl_error): two warm-up frames (the driver's shader JIT, maps drawn once), then `frames`
// frames of render + glFinish with no readback. Needs a current GL context.
#pragma once

#include "gl/render_target.h"
#include "render/forward_renderer.h"
#include "scene/scene.h"

namespace bounce::test {

struct FrameTime {
  double wallMs = 0.0;  // median wall time of one frame, ms
  double cpuMs = 0.0;   // mean process CPU time of one frame (all llvmpipe threads), ms
};

// The median ignores frames another process slowed down; the CPU time is the steadier figure on
// a shared machine (≈ wall × threads on an idle one).
FrameTime frameMilliseconds(ForwardRenderer& renderer, const Camera& camera,
                            gl::RenderTarget& target, int frames);

}  // namespace bounce::test
