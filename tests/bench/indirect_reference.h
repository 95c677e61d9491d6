// The path-traced indirect-only reference frame of the accuracy benches (bench_indirect_accuracy,
// bench_vpl_error), cached as two EXR files so a sweep traces it once: `file` holds the radiance
// (W/(sr·m²)), `<file stem>.se.exr` each pixel's standard error of the mean (same unit).
#pragma once

#include <string>

#include "indirect_accuracy.h"

namespace bounce::test {

// Reads the pair when both files exist (throws if the frame is not size × size pixels); otherwise
// traces a size × size frame at `spp` samples per pixel (traceIndirectReference) and, when `file`
// is not empty, writes the pair. Progress lines on stderr start with `program`.
Reference cachedIndirectReference(const Scene& scene, const Camera& camera, int size, int spp,
                                  const std::string& file, const char* program);

}  // namespace bounce::test
