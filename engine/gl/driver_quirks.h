// Driver behaviour the GL layer works around, each a named, commented flag (the model is
// Filament's OpenGLContext `bugs`). Private to the GL layer; the flags are facts measured on
// Mesa 22.3 (llvmpipe, the Debian 12 package; docs/dependencies.md), kept in one place so a new
// driver is one edit.
#pragma once

namespace bounce::gl {

struct DriverQuirks {
  // OSMesa: OSMesaMakeCurrent() refuses a null colour buffer even though every bounce pass
  // renders into an FBO; we hand it a 1x1 client buffer that nothing ever draws to.
  bool osmesaNeedsClientBuffer = true;

  // EGL: eglGetDisplay(EGL_DEFAULT_DISPLAY) fails without an X server (unless the environment
  // sets EGL_PLATFORM=surfaceless), so displays are asked for by platform: Mesa's surfaceless
  // platform first (any machine, llvmpipe without a GPU), then the device platform (GPU drivers
  // without Mesa's extension, e.g. NVIDIA headless).
  bool eglDefaultDisplayNeedsX = true;

  // glReadPixels returns rows bottom-up (GL's window origin is the lower-left corner) while
  // bounce::Image is top-down; OSMesa's client buffer is bottom-up too. Readback flips rows.
  bool readPixelsBottomUp = true;

  // Compile logs name the source string and line as "S:L(C): error: ..." (Mesa) or
  // "S(L) : error ..." (NVIDIA, AMD); shader.cpp rewrites both to "file:L: ...".
  bool logFormatsDiffer = true;

  // Under AddressSanitizer: GLX and EGL unload Mesa's driver (swrast_dri.so, libGLX_mesa) when
  // the last context or display goes, so LeakSanitizer's report at exit shows the driver's own
  // allocations as "<unknown module>" that no suppression can name. Sanitized builds pin every
  // loaded GL driver with RTLD_NODELETE (gl_functions.cpp); normal builds leave them alone.
  bool driversUnloadBeforeLeakCheck = true;

  // llvmpipe: a GL_TIME_ELAPSED query that spans a scene flush (a shadow map drawn and then
  // sampled within it) reports end − 0, the machine's uptime (434,645 ms for the Cornell box's
  // lit pass at 440 s uptime). Pass timers use pairs of GL_TIMESTAMP queries instead
  // (gpu_pass_timers.h).
  bool timeElapsedAcrossFlushes = true;
};

inline constexpr DriverQuirks kDriverQuirks{};

}  // namespace bounce::gl
