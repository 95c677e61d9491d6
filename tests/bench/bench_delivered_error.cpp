// The error a bake reports against the error it delivers (issue 28, measured item 4; docs/baker.md,
// "Estimated error"): reads a bake folder and a converged bake of the same texels (same scene,
// texel size and seed; --target-error 0 and a large --spp) and prints, over the texels with
// samples of their own (error.exr ≠ −1) where both maps are lit and the texel was not filled
// from its neighbours (error.exr ≠ 1, delivered_error.h):
//   measured   mean and p95 of |E − E_conv| / E_conv (luminance), Σ|E − E_conv| / Σ E_conv
//   error.exr  mean and p95 of the bake's estimate over the same texels
//   bake.json  its estimatedError (over every lit texel with samples, the filled ones as 1)
//   converged  the converged bake's own estimate (its error is part of "measured")
// and the ratios estimated / measured. Run by hand:
//   bench_delivered_error BAKE_DIR CONVERGED_DIR
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <vector>

#include <nlohmann/json.hpp>

#include "bake/error_summary.h"
#include "image/image_io.h"
#include "image/luminance.h"

namespace {

nlohmann::json estimatedError(const std::filesystem::path& dir) {
  std::ifstream in(dir / "bake.json");
  if (!in) throw std::runtime_error((dir / "bake.json").string() + ": cannot be read");
  return nlohmann::json::parse(in).at("estimatedError");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: bench_delivered_error BAKE_DIR CONVERGED_DIR\n");
    return 2;
  }
  try {
    const std::filesystem::path bakeDir = argv[1], convergedDir = argv[2];
    const bounce::Image map = bounce::readExr(bakeDir / "lightmap.exr");
    const bounce::Image errors = bounce::readExr(bakeDir / "error.exr");
    const bounce::Image converged = bounce::readExr(convergedDir / "lightmap.exr");
    if (map.width != converged.width || map.height != converged.height)
      throw std::runtime_error(convergedDir.string() + ": its atlas is " +
                               std::to_string(converged.width) + "x" +
                               std::to_string(converged.height) + ", the bake's " +
                               std::to_string(map.width) + "x" + std::to_string(map.height));
    std::vector<float> relative;
    std::vector<float> reported;
    std::size_t black = 0, filled = 0;
    double filledError = 0, filledDifference = 0, filledLight = 0;
    std::vector<float> tame, tameReported;
    std::size_t outliers = 0;
    double outlierLight = 0;
    double differenceSum = 0, convergedSum = 0;
    for (std::size_t t = 0; t < map.pixels.size(); ++t) {
      const float c = bounce::luminance(converged.pixels[t]);
      const float delivered = bounce::luminance(map.pixels[t]);
      if (errors.pixels[t].r < 0.0f || !(c > 0.0f)) continue;
      // The bake's figures leave out texels it delivers black (no sample found light) and
      // count those filled from their neighbours as 1 (error.exr holds 1 exactly).
      if (!(delivered > 0.0f)) {
        ++black;
        continue;
      }
      if (errors.pixels[t].r == 1.0f) {
        ++filled;
        filledError += std::abs(delivered - c) / c;
        filledDifference += std::abs(delivered - c);
        filledLight += c;
        continue;
      }
      reported.push_back(errors.pixels[t].r);
      // A texel the converged bake holds nearly black makes any difference huge relative to
      // it: the mean is given with and without the texels over 200% (their count printed).
      if (std::abs(delivered - c) / c > 2.0f) {
        ++outliers;
        outlierLight += c;
      } else {
        tame.push_back(std::abs(delivered - c) / c);
        tameReported.push_back(errors.pixels[t].r);
      }
      const float d = std::abs(bounce::luminance(map.pixels[t]) - c);
      relative.push_back(d / c);
      differenceSum += d;
      convergedSum += c;
    }
    if (relative.empty()) throw std::runtime_error("no texel to compare");
    const bounce::ErrorSummary measured = bounce::summariseErrors(relative),
                               estimated = bounce::summariseErrors(reported);
    const double weighted = differenceSum / convergedSum;
    const nlohmann::json manifest = estimatedError(bakeDir), own = estimatedError(convergedDir);
    std::printf(
        "texels %zu compared; left out: %zu delivered black, %zu filled from their "
        "neighbours (error.exr 1)\n",
        relative.size(), black, filled);
    if (filled > 0)
      std::printf("filled     measured mean %.4f, luminance-weighted %.4f\n",
                  filledError / static_cast<double>(filled), filledDifference / filledLight);
    std::printf("measured   mean %.4f p95 %.4f luminance-weighted %.4f\n", measured.mean,
                measured.p95, weighted);
    std::printf("error.exr  mean %.4f p95 %.4f (the same texels)\n", estimated.mean, estimated.p95);
    std::printf(
        "bake.json  mean %.4f p95 %.4f luminance-weighted %.4f (before filters mean "
        "%.4f p95 %.4f)\n",
        manifest.at("mean").get<double>(), manifest.at("p95").get<double>(),
        manifest.value("luminanceWeighted", 0.0),
        manifest.contains("beforeFilters") ? manifest["beforeFilters"].value("mean", 0.0) : 0.0,
        manifest.contains("beforeFilters") ? manifest["beforeFilters"].value("p95", 0.0) : 0.0);
    std::printf("converged  its own bake.json mean %.4f p95 %.4f\n", own.at("mean").get<double>(),
                own.at("p95").get<double>());
    if (outliers > 0 && !tame.empty()) {
      const bounce::ErrorSummary m = bounce::summariseErrors(tame),
                                 r = bounce::summariseErrors(tameReported);
      std::printf(
          "without the %zu texels over 200%% (converged E %.3g W/m2 on average): measured "
          "mean %.4f p95 %.4f, error.exr mean %.4f p95 %.4f, ratio %.3f %.3f\n",
          outliers, outlierLight / static_cast<double>(outliers), m.mean, m.p95, r.mean, r.p95,
          r.mean / m.mean, r.p95 / m.p95);
    }
    std::printf("ratio estimated/measured: mean %.3f p95 %.3f luminance-weighted %.3f\n",
                estimated.mean / measured.mean, estimated.p95 / measured.p95,
                manifest.value("luminanceWeighted", 0.0) / weighted);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_delivered_error: %s\n", e.what());
    return 1;
  }
  return 0;
}
