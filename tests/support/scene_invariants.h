// What a successfully loaded Scene promises the renderer and the tracer (docs/input_limits.md):
// every index in range, every value finite, world coordinates within the stated limit, light
// and emission products finite. The fuzz targets abort and the corpus test fails when one is
// broken, so a loader that lets a bad file through is a finding, not only a crash.
#pragma once

#include <cmath>
#include <string>

#include "scene/scene.h"

namespace bounce::test {

// Empty when the scene keeps every promise, else the first broken one.
std::string brokenInvariant(const Scene& scene);

}  // namespace bounce::test
