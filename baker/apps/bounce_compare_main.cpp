// bounce-compare: error metrics of a linear EXR image against a reference EXR
// (engine/image/image_compare.h), as a table or JSON, with an optional false-colour error image.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

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

struct Options {
  std::string image, reference, mask, errorImage;
  std::optional<float> errorScale;
  bool json = false;
  bool allowNonFinite = false;
  int box = 1;
};

void addOptions(CLI::App& app, Options& o) {
  app.add_option("A", o.image, "image to assess (linear EXR)")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("B", o.reference, "reference image (linear EXR)")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("--mask", o.mask, "PNG mask: pixels whose value is 0 are excluded")
      ->check(CLI::ExistingFile);
  app.add_option("--box", o.box,
                 "A is K times B's size in each direction: average each KxK block of A first "
                 "(a supersampled raster against the tracer's area-averaged pixels)")
      ->check(CLI::Range(1, 64));
  app.add_flag("--json", o.json, "print the metrics as JSON");
  app.add_flag(
      "--allow-nonfinite", o.allowNonFinite,
      "exit 0 even when the image or the reference has NaN/Inf pixels (they are excluded from "
      "the metrics, and counted)");
  app.add_option("--error-image", o.errorImage,
                 "write a false-colour PNG of |a-b|/(|b|+0.01) (blue 0 ... red >= scale)");
  app.add_option("--error-scale", o.errorScale,
                 "relative error shown as red (default: the 99th percentile of the map)")
      ->check(CLI::PositiveNumber);
}

// A refused input: the message already names the files.
struct Refusal : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A (box-averaged by --box), B and the mask, their sizes checked against each other.
struct Inputs {
  bounce::Image a, b;
  std::optional<bounce::Mask> mask;
};

Inputs readInputs(const Options& o) {
  Inputs in;
  in.a = bounce::readExr(o.image);
  if (o.box > 1) {
    if (in.a.width % o.box != 0 || in.a.height % o.box != 0)
      throw Refusal(o.image + ": " + std::to_string(in.a.width) + "x" +
                    std::to_string(in.a.height) + " is not a multiple of --box " +
                    std::to_string(o.box));
    in.a = bounce::boxDownsample(in.a, o.box);
  }
  in.b = bounce::readExr(o.reference);
  if (!o.mask.empty()) {
    in.mask = bounce::readMask(o.mask);
    if (in.mask->width != in.b.width || in.mask->height != in.b.height)
      throw Refusal(o.mask + ": mask size " + std::to_string(in.mask->width) + "x" +
                    std::to_string(in.mask->height) + " differs from the reference " + o.reference +
                    "'s " + std::to_string(in.b.width) + "x" + std::to_string(in.b.height));
  }
  return in;
}

nlohmann::json metricsJson(const Options& o, const bounce::ImageError& error) {
  return {{"image", o.image},
          {"reference", o.reference},
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
}

// --error-image: |a-b|/(|b|+0.01) in false colour, red at --error-scale or else at the 99th
// percentile of the compared pixels' relative error.
void writeErrorImage(const Options& o, const Inputs& in, nlohmann::json& out) {
  const bounce::Mask* mask = in.mask ? &*in.mask : nullptr;
  const std::vector<float> r = bounce::relativeErrorMap(in.a, in.b, mask);
  float scale = o.errorScale.value_or(0.0f);
  if (!o.errorScale) {
    std::vector<float> kept;
    for (std::size_t i = 0; i < r.size(); ++i)
      if (!mask || mask->keep[i] != 0) kept.push_back(r[i]);
    if (!kept.empty()) {
      const auto rank = static_cast<std::size_t>(0.99 * static_cast<double>(kept.size() - 1));
      std::nth_element(kept.begin(), kept.begin() + static_cast<std::ptrdiff_t>(rank), kept.end());
      scale = kept[rank];
    }
    if (!(scale > 0.0f)) scale = 1.0f;  // identical images: everything is blue
  }
  bounce::writeDisplayPng(o.errorImage,
                          bounce::falseColour(r, in.b.width, in.b.height, scale, mask));
  out["errorImage"] = {
      {"path", o.errorImage}, {"metric", "|a-b|/(|b|+0.01), channel mean"}, {"redAt", scale}};
  if (!o.json)
    std::printf("error image %s: |a-b|/(|b|+%g) averaged over channels; blue = 0, red >= %g\n",
                o.errorImage.c_str(), bounce::kRelErrorEpsilon, static_cast<double>(scale));
}

// Metrics over no pixel, or over only the finite part of a broken render, would read as "no
// error": both fail unless the caller accepts them.
void refuseEmptyOrNonFinite(const Options& o, const bounce::ImageError& error) {
  if (error.comparedPixels == 0)
    throw Refusal(o.image + " vs " + o.reference + ": no pixel to compare (" +
                  std::to_string(error.nonFinitePixels) + " non-finite, the rest masked out)");
  if (error.nonFiniteInReference > 0 && !o.allowNonFinite)
    throw Refusal(o.reference + ": " + std::to_string(error.nonFiniteInReference) +
                  " reference pixels are NaN/Inf (excluded from the metrics; --allow-nonfinite "
                  "accepts this)");
  if (error.nonFiniteInImage > 0 && !o.allowNonFinite)
    throw Refusal(o.image + ": " + std::to_string(error.nonFiniteInImage) +
                  " pixels are NaN/Inf (excluded from the metrics; --allow-nonfinite accepts "
                  "this)");
}

void run(const Options& o) {
  const Inputs in = readInputs(o);
  const bounce::ImageError error = bounce::compareImages(in.a, in.b, in.mask ? &*in.mask : nullptr);
  nlohmann::json out = metricsJson(o, error);
  if (!o.json) printTable(error);
  if (!o.errorImage.empty()) writeErrorImage(o, in, out);
  if (o.json) std::cout << out.dump(2) << "\n";
  refuseEmptyOrNonFinite(o, error);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Compares a linear EXR image A with a reference EXR image B: RMSE, relative MSE, mean "
      "absolute relative error, bias and 99th-percentile absolute error, per channel and over "
      "all."};
  Options o;
  addOptions(app, o);
  CLI11_PARSE(app, argc, argv);
  try {
    run(o);
  } catch (const Refusal& e) {
    std::cerr << "bounce-compare: " << e.what() << "\n";
    return 1;
  } catch (const std::invalid_argument& e) {  // sizes differ
    std::cerr << "bounce-compare: " << o.image << " vs " << o.reference << ": " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "bounce-compare: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
