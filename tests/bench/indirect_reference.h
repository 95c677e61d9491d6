// The path-traced reference frame of the accuracy benches (bench_indirect_accuracy,
// bench_vpl_error; indirect-only unless asked), cached as two EXR files so a sweep traces it once:
// `file` holds the radiance (W/(sr·m²)), `<file stem>.se.exr` each pixel's standard error of the
// mean (same unit).
#pragma once

#include <string>

#include "indirect_accuracy.h"

namespace bounce::test {

// Reads the pair when both files exist (throws if the frame is not width × height pixels);
// otherwise traces a width × height frame of `paths` at `spp` samples per pixel (traceReference)
// and, when `file` is not empty, writes the pair. Progress lines on stderr start with `program`.
Reference cachedReference(const Scene& scene, const Camera& camera, int width, int height, int spp,
                          PathSet paths, const std::string& file, const char* program);

inline Reference cachedIndirectReference(const Scene& scene, const Camera& camera, int size,
                                         int spp, const std::string& file, const char* program) {
  return cachedReference(scene, camera, size, size, spp, PathSet::IndirectOnly, file, program);
}

}  // namespace bounce::test
