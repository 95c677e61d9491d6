// Image files. EXR holds linear values as 32-bit float RGB; PNG holds tone-mapped 8-bit sRGB
// (see tonemap.h). Writers are atomic (atomic_file.h); every failure throws
// std::runtime_error naming the file and the reason.
#pragma once

#include <filesystem>

#include "image/image.h"

namespace bounce {

void writeExr(const std::filesystem::path& path, const Image& image);
Image readExr(const std::filesystem::path& path);
void writePng(const std::filesystem::path& path, const Image& radiance, float exposureEV);
// Writes by extension: ".exr" linear, ".png" tone-mapped.
void writeImage(const std::filesystem::path& path, const Image& image, float exposureEV);

}  // namespace bounce
