// lightmap_flux_error: a lightmap's error against a converged bake of the same texels, weighted
// by the light (docs/baker.md "Gather with a cache"). With Y the luminance of the irradiance
// (W/m²) of texel i in A and in the reference R, over the texels where either is not 0:
//   relL1   = Σ|Y_A − Y_R| / Σ Y_R      (the error a frame shows, bright texels counting more)
//   relRmse = sqrt(mean (Y_A − Y_R)²) / mean Y_R
//   bias    = Σ(Y_A − Y_R) / Σ Y_R
// Unlike bounce-compare's per-pixel relative error it is not ruled by dim texels, where a
// converged bake of a real room is itself noisiest.
//
//   lightmap_flux_error A/lightmap.exr REF/lightmap.exr      (prints: relL1 relRmse bias texels)
#include <cmath>
#include <cstdio>
#include <exception>

#include "image/image_io.h"
#include "trace/sampling.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: lightmap_flux_error A.exr REF.exr\n");
    return 2;
  }
  try {
    const bounce::Image a = bounce::readExr(argv[1]), ref = bounce::readExr(argv[2]);
    if (a.width != ref.width || a.height != ref.height) {
      std::fprintf(stderr, "lightmap_flux_error: %s is %dx%d, %s %dx%d\n", argv[1], a.width,
                   a.height, argv[2], ref.width, ref.height);
      return 1;
    }
    double sumRef = 0.0, sumAbs = 0.0, sumDiff = 0.0, sumSq = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
      const double ya = bounce::luminance(a.pixels[i]), yr = bounce::luminance(ref.pixels[i]);
      if (ya == 0.0 && yr == 0.0) continue;
      sumRef += yr;
      sumAbs += std::abs(ya - yr);
      sumDiff += ya - yr;
      sumSq += (ya - yr) * (ya - yr);
      ++n;
    }
    const double meanRef = sumRef / static_cast<double>(n);
    std::printf("%.6f %.6f %+.6f %zu\n", sumAbs / sumRef,
                std::sqrt(sumSq / static_cast<double>(n)) / meanRef, sumDiff / sumRef, n);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lightmap_flux_error: %s\n", e.what());
    return 1;
  }
}
