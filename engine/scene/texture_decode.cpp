#include "scene/texture_decode.h"

#include <stb_image.h>

#include <cmath>
#include <stdexcept>

#include "io/load_error.h"
#include "io/regular_file.h"
#include "scene/input_limits.h"

namespace bounce {

float srgbToLinear(float encoded) {
  return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

std::string textureSizeProblem(int width, int height) {
  if (width <= 0 || height <= 0) return "image has no pixels";
  if (width > kMaxTextureSide || height > kMaxTextureSide ||
      static_cast<std::size_t>(width) * static_cast<std::size_t>(height) > kMaxTextureTexels) {
    return "image of " + std::to_string(width) + "x" + std::to_string(height) +
           " texels exceeds bounce's texture limit (at most 16384 per side, the GL maximum of "
           "llvmpipe, and 2^26 texels in all; docs/input_limits.md)";
  }
  return {};
}

Texture decodeSrgbTexture(std::string name, int width, int height, int components, int bits,
                          std::span<const unsigned char> data) {
  if (const std::string problem = textureSizeProblem(width, height); !problem.empty())
    throw std::invalid_argument(problem);
  if (components < 1 || components > 4) {
    throw std::invalid_argument("image has " + std::to_string(components) + " channels");
  }
  if (bits != 8 && bits != 16) {
    throw std::invalid_argument("image has " + std::to_string(bits) + " bits per channel");
  }
  const std::size_t bytesPerValue = static_cast<std::size_t>(bits / 8);
  const std::size_t texels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  if (data.size() != texels * static_cast<std::size_t>(components) * bytesPerValue) {
    throw std::invalid_argument("image data size does not match its dimensions");
  }
  // A lookup table per encoded value keeps 8-bit decoding cheap and exact to float precision.
  const std::size_t levels = bits == 8 ? 256 : 65536;
  std::vector<float> linear(levels);
  for (std::size_t v = 0; v < levels; ++v) {
    linear[v] = srgbToLinear(static_cast<float>(v) / static_cast<float>(levels - 1));
  }
  auto value = [&](std::size_t i) -> float {
    if (bits == 8) return linear[data[i]];
    // tinygltf and stb return 16-bit values in native (little-endian) order.
    const auto v =
        static_cast<std::size_t>(data[2 * i]) | (static_cast<std::size_t>(data[2 * i + 1]) << 8);
    return linear[v];
  };
  Texture texture;
  texture.name = std::move(name);
  texture.width = width;
  texture.height = height;
  texture.texels.resize(texels);
  const auto c = static_cast<std::size_t>(components);
  for (std::size_t t = 0; t < texels; ++t) {
    const std::size_t base = t * c;
    texture.texels[t] = components >= 3 ? glm::vec3(value(base), value(base + 1), value(base + 2))
                                        : glm::vec3(value(base));
  }
  return texture;
}

Texture readSrgbTextureFile(const std::filesystem::path& file, const std::filesystem::path& image) {
  std::vector<unsigned char> bytes;
  try {
    bytes = readRegularFile(image);
  } catch (const std::runtime_error& e) {
    throw LoadError(file, std::string("cannot read texture: ") + e.what());
  }
  if (bytes.size() > static_cast<std::size_t>(INT32_MAX))
    throw LoadError(file, "texture '" + image.string() + "' is larger than 2 GiB");
  const int byteCount = static_cast<int>(bytes.size());
  int width = 0, height = 0, components = 0;
  // The size from the header, before decoding allocates width × height texels.
  if (stbi_info_from_memory(bytes.data(), byteCount, &width, &height, &components) != 0) {
    if (const std::string problem = textureSizeProblem(width, height); !problem.empty())
      throw LoadError(file, "texture '" + image.string() + "': " + problem);
  }
  unsigned char* pixels =
      stbi_load_from_memory(bytes.data(), byteCount, &width, &height, &components, 3);
  if (pixels == nullptr) {
    throw LoadError(file, "cannot read texture '" + image.string() + "': " + stbi_failure_reason());
  }
  const std::size_t size = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3;
  Texture texture;
  try {
    texture = decodeSrgbTexture(image.filename().string(), width, height, 3, 8,
                                std::span<const unsigned char>(pixels, size));
  } catch (const std::invalid_argument& e) {
    stbi_image_free(pixels);
    throw LoadError(file, "texture '" + image.string() + "': " + e.what());
  }
  stbi_image_free(pixels);
  return texture;
}

}  // namespace bounce
