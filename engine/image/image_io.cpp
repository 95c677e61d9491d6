#include "image/image_io.h"

#include <stb/stb_image_write.h>
#include <tinyexr.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "image/atomic_file.h"
#include "image/tonemap.h"

namespace bounce {
namespace {

std::string takeExrError(const char* err) {
  std::string message = err ? err : "unknown tinyexr error";
  if (err) FreeEXRErrorMessage(err);
  return message;
}

void requireSize(const std::filesystem::path& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() !=
          static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height))
    throw std::runtime_error(path.string() + ": refusing to write an image of size " +
                             std::to_string(image.width) + "x" + std::to_string(image.height));
}

}  // namespace

void writeExr(const std::filesystem::path& path, const Image& image) {
  requireSize(path, image);
  // EXR stores channels by name in alphabetical order: B, G, R.
  std::vector<float> planes[3];
  for (auto& plane : planes) plane.reserve(image.pixels.size());
  for (const glm::vec3& p : image.pixels) {
    planes[0].push_back(p.b);
    planes[1].push_back(p.g);
    planes[2].push_back(p.r);
  }
  float* planePointers[3] = {planes[0].data(), planes[1].data(), planes[2].data()};

  EXRHeader header;
  InitEXRHeader(&header);
  EXRImage exr;
  InitEXRImage(&exr);
  exr.num_channels = 3;
  exr.images = reinterpret_cast<unsigned char**>(planePointers);
  exr.width = image.width;
  exr.height = image.height;
  EXRChannelInfo channels[3] = {};
  int pixelTypes[3] = {TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT};
  const char* names[3] = {"B", "G", "R"};
  for (int c = 0; c < 3; ++c)
    std::snprintf(channels[c].name, sizeof(channels[c].name), "%s", names[c]);
  header.num_channels = 3;
  header.channels = channels;
  header.pixel_types = pixelTypes;
  header.requested_pixel_types = pixelTypes;
  header.compression_type = TINYEXR_COMPRESSIONTYPE_ZIP;

  unsigned char* memory = nullptr;
  const char* err = nullptr;
  const std::size_t size = SaveEXRImageToMemory(&exr, &header, &memory, &err);
  if (size == 0)
    throw std::runtime_error(path.string() + ": cannot encode EXR: " + takeExrError(err));
  std::unique_ptr<unsigned char, decltype(&std::free)> owned(memory, &std::free);
  writeFileAtomically(path, {memory, size});
}

Image readExr(const std::filesystem::path& path) {
  float* rgba = nullptr;
  int width = 0;
  int height = 0;
  const char* err = nullptr;
  if (LoadEXR(&rgba, &width, &height, path.c_str(), &err) != TINYEXR_SUCCESS)
    throw std::runtime_error(path.string() + ": cannot read EXR: " + takeExrError(err));
  std::unique_ptr<float, decltype(&std::free)> owned(rgba, &std::free);
  Image image(width, height);
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    image.pixels[i] = {rgba[4 * i + 0], rgba[4 * i + 1], rgba[4 * i + 2]};
  return image;
}

void writePng(const std::filesystem::path& path, const Image& radiance, float exposureEV) {
  requireSize(path, radiance);
  std::vector<unsigned char> rgb;
  rgb.reserve(radiance.pixels.size() * 3);
  for (const glm::vec3& p : radiance.pixels) {
    const glm::vec3 display = toneMap(p, exposureEV);
    for (int c = 0; c < 3; ++c)
      rgb.push_back(static_cast<unsigned char>(std::lround(display[c] * 255.0f)));
  }
  std::vector<unsigned char> encoded;
  auto append = [](void* context, void* data, int size) {
    auto* out = static_cast<std::vector<unsigned char>*>(context);
    const auto* bytes = static_cast<const unsigned char*>(data);
    out->insert(out->end(), bytes, bytes + size);
  };
  if (!stbi_write_png_to_func(append, &encoded, radiance.width, radiance.height, 3, rgb.data(),
                              radiance.width * 3))
    throw std::runtime_error(path.string() + ": cannot encode PNG");
  writeFileAtomically(path, encoded);
}

void writeImage(const std::filesystem::path& path, const Image& image, float exposureEV) {
  const std::string ext = path.extension().string();
  if (ext == ".exr") return writeExr(path, image);
  if (ext == ".png") return writePng(path, image, exposureEV);
  throw std::runtime_error(path.string() + ": unknown image extension '" + ext +
                           "' (expected .exr or .png)");
}

}  // namespace bounce
