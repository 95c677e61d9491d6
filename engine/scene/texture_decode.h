// Decoding of 8/16-bit image texels into the scene's linear-RGB textures.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include "scene/scene.h"

namespace bounce {

// The sRGB transfer function inverted (IEC 61966-2-1): encoded value in [0,1] → linear.
float srgbToLinear(float encoded);

// Empty when a width × height texture is within bounce's limits (input_limits.h), else the
// reason, naming the size and the limit.
std::string textureSizeProblem(int width, int height);

// Builds a linear texture from interleaved sRGB-encoded texels, rows top first.
// `components` 1 (grey), 2 (grey, alpha), 3 (RGB) or 4 (RGBA; alpha ignored); `bits` 8 or 16.
// Throws std::invalid_argument when the sizes do not match the data or exceed the limits.
Texture decodeSrgbTexture(std::string name, int width, int height, int components, int bits,
                          std::span<const unsigned char> data);

// Reads an image file (PNG, JPEG, … through stb_image) as an sRGB texture.
// Throws LoadError naming `file` (the referencing scene file) and the image.
Texture readSrgbTextureFile(const std::filesystem::path& file, const std::filesystem::path& image);

}  // namespace bounce
