// Image files. EXR holds linear values as 32-bit float RGB; PNG holds tone-mapped 8-bit sRGB
// (see tonemap.h). Writers are atomic (atomic_file.h); every failure throws
// std::runtime_error naming the file and the reason. readExr reads regular files only and
// refuses UINT channels (HALF and FLOAT hold radiance; UINT would be read as float bits).
#pragma once

#include <filesystem>
#include <span>
#include <vector>

#include "image/image.h"

namespace bounce {

void writeExr(const std::filesystem::path& path, const Image& image);
Image readExr(const std::filesystem::path& path);
void writePng(const std::filesystem::path& path, const Image& radiance, float exposureEV);
// A PNG of display values in [0, 1] (sRGB-encoded already, e.g. a window's pixels): no tone map.
void writeDisplayPng(const std::filesystem::path& path, const Image& display);
// Writes by extension: ".exr" linear, ".png" tone-mapped.
void writeImage(const std::filesystem::path& path, const Image& image, float exposureEV);
// The bytes writeImage would write (by extension; other extensions throw).
std::vector<unsigned char> encodeImage(const std::filesystem::path& path, const Image& image,
                                       float exposureEV);

// One output of a tool run: `image` written to `path` by its extension.
struct ImageOutput {
  std::filesystem::path path;
  const Image* image = nullptr;
  float exposureEV = 0.0f;  // PNG only
};
// Every output or none (atomic_file.h, writeFilesAtomically): all are encoded and written to
// temporary files before any target is replaced.
void writeImages(std::span<const ImageOutput> outputs);

}  // namespace bounce
