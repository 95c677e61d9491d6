// bounce-compare: error metrics of a linear EXR image against a reference EXR
// (engine/image/image_compare.h), as a table or JSON, with an optional false-colour error image.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <iostream>
#include <optional>
#include <string>

#include "image/image_compare.h"
#include "image/image_io.h"

namespace {

nlohmann::json toJson(const bounce::ChannelError& e) {
  return {{"rmse", e.rmse},
          {"relMse", e.relMse},
          {"meanAbsRelError", e.meanAbsRelError},
          {"bias", e.bias},
          {"p99AbsError", e.p99AbsError}};
}

void printTable(const bounce::ImageError& error) {
  std::printf(
      "compared pixels: %zu (non-finite, excluded: %zu; %zu in the image, %zu in the "
      "reference)\n",
      error.comparedPixels, error.nonFinitePixels, error.nonFiniteInImage,
      error.nonFiniteInReference);
  std::printf("%-4s %12s %12s %12s %13s %12s\n", "", "RMSE", "relMSE", "meanAbsRel", "bias",
              "p99|a-b|");
  const char* names[4] = {"R", "G", "B", "all"};
  for (int c = 0; c < 4; ++c) {
    const bounce::ChannelError& e = c < 3 ? error.channels[static_cast<std::size_t>(c)] : error.all;
    std::printf("%-4s %12.6g %12.6g %12.6g %+13.6g %12.6g\n", names[c], e.rmse, e.relMse,
                e.meanAbsRelError, e.bias, e.p99AbsError);
  }
  std::printf(
      "relMSE = mean((a-b)^2 / (b^2 + %g)); meanAbsRel = mean(|a-b| / (|b| + %g)); "
      "b is the reference\n",
      bounce::kRelMseEpsilon, bounce::kRelErrorEpsilon);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Compares a linear EXR image A with a reference EXR image B: RMSE, relative MSE, mean "
      "absolute relative error, bias and 99th-percentile absolute error, per channel and over "
      "all."};
  std::string imagePath, referencePath, maskPath, errorImagePath;
  std::optional<float> errorScale;
  bool json = false;
  bool allowNonFinite = false;
  int box = 1;
  app.add_option("A", imagePath, "image to assess (linear EXR)")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("B", referencePath, "reference image (linear EXR)")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("--mask", maskPath, "PNG mask: pixels whose value is 0 are excluded")
      ->check(CLI::ExistingFile);
  app.add_option("--box", box,
                 "A is K times B's size in each direction: average each KxK block of A first "
                 "(a supersampled raster against the tracer's area-averaged pixels)")
      ->check(CLI::Range(1, 64));
  app.add_flag("--json", json, "print the metrics as JSON");
  app.add_flag(
      "--allow-nonfinite", allowNonFinite,
      "exit 0 even when the image or the reference has NaN/Inf pixels (they are excluded from "
      "the metrics, and counted)");
  app.add_option("--error-image", errorImagePath,
                 "write a false-colour PNG of |a-b|/(|b|+0.01) (blue 0 ... red >= scale)");
  app.add_option("--error-scale", errorScale,
                 "relative error shown as red (default: the 99th percentile of the map)")
      ->check(CLI::PositiveNumber);
  CLI11_PARSE(app, argc, argv);

  try {
    bounce::Image a = bounce::readExr(imagePath);
    if (box > 1) {
      if (a.width % box != 0 || a.height % box != 0) {
        std::cerr << "bounce-compare: " << imagePath << ": " << a.width << "x" << a.height
                  << " is not a multiple of --box " << box << "\n";
        return 1;
      }
      a = bounce::boxDownsample(a, box);
    }
    const bounce::Image b = bounce::readExr(referencePath);
    std::optional<bounce::Mask> mask;
    if (!maskPath.empty()) {
      mask = bounce::readMask(maskPath);
      if (mask->width != b.width || mask->height != b.height) {
        std::cerr << "bounce-compare: " << maskPath << ": mask size " << mask->width << "x"
                  << mask->height << " differs from the reference " << referencePath << "'s "
                  << b.width << "x" << b.height << "\n";
        return 1;
      }
    }
    const bounce::Mask* maskPtr = mask ? &*mask : nullptr;
    const bounce::ImageError error = bounce::compareImages(a, b, maskPtr);

    nlohmann::json out = {{"image", imagePath},
                          {"reference", referencePath},
                          {"comparedPixels", error.comparedPixels},
                          {"nonFinitePixels", error.nonFinitePixels},
                          {"nonFiniteInImage", error.nonFiniteInImage},
                          {"nonFiniteInReference", error.nonFiniteInReference},
                          {"relMseEpsilon", bounce::kRelMseEpsilon},
                          {"relErrorEpsilon", bounce::kRelErrorEpsilon},
                          {"channels",
                           {{"r", toJson(error.channels[0])},
                            {"g", toJson(error.channels[1])},
                            {"b", toJson(error.channels[2])}}},
                          {"all", toJson(error.all)}};
    if (!json) printTable(error);

    if (!errorImagePath.empty()) {
      const std::vector<float> r = bounce::relativeErrorMap(a, b, maskPtr);
      float scale = errorScale.value_or(0.0f);
      if (!errorScale) {  // 99th percentile of the compared pixels' relative error
        std::vector<float> kept;
        for (std::size_t i = 0; i < r.size(); ++i)
          if (!maskPtr || maskPtr->keep[i] != 0) kept.push_back(r[i]);
        if (!kept.empty()) {
          const auto rank = static_cast<std::size_t>(0.99 * static_cast<double>(kept.size() - 1));
          std::nth_element(kept.begin(), kept.begin() + static_cast<std::ptrdiff_t>(rank),
                           kept.end());
          scale = kept[rank];
        }
        if (!(scale > 0.0f)) scale = 1.0f;  // identical images: everything is blue
      }
      bounce::writeDisplayPng(errorImagePath,
                              bounce::falseColour(r, b.width, b.height, scale, maskPtr));
      out["errorImage"] = {
          {"path", errorImagePath}, {"metric", "|a-b|/(|b|+0.01), channel mean"}, {"redAt", scale}};
      if (!json) {
        std::printf("error image %s: |a-b|/(|b|+%g) averaged over channels; blue = 0, red >= %g\n",
                    errorImagePath.c_str(), bounce::kRelErrorEpsilon, static_cast<double>(scale));
      }
    }
    if (json) std::cout << out.dump(2) << "\n";
    // Metrics over no pixel, or over only the finite part of a broken render, would read as
    // "no error": both fail unless the caller accepts them.
    if (error.comparedPixels == 0) {
      std::cerr << "bounce-compare: " << imagePath << " vs " << referencePath
                << ": no pixel to compare (" << error.nonFinitePixels
                << " non-finite, the rest masked out)\n";
      return 1;
    }
    if (error.nonFiniteInReference > 0 && !allowNonFinite) {
      std::cerr << "bounce-compare: " << referencePath << ": " << error.nonFiniteInReference
                << " reference pixels are NaN/Inf (excluded from the metrics; --allow-nonfinite "
                   "accepts this)\n";
      return 1;
    }
    if (error.nonFiniteInImage > 0 && !allowNonFinite) {
      std::cerr << "bounce-compare: " << imagePath << ": " << error.nonFiniteInImage
                << " pixels are NaN/Inf (excluded from the metrics; --allow-nonfinite accepts "
                   "this)\n";
      return 1;
    }
  } catch (const std::invalid_argument& e) {  // sizes differ
    std::cerr << "bounce-compare: " << imagePath << " vs " << referencePath << ": " << e.what()
              << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "bounce-compare: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
