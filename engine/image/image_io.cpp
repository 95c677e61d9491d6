#include "image/image_io.h"

#include <stb/stb_image_write.h>
#include <tinyexr.h>
#include <algorithm>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "image/tonemap.h"
#include "io/atomic_file.h"
#include "io/regular_file.h"

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

// tinyexr 1.0.1's header parser assert()s (aborting the process) on two header attributes it
// does not validate: a `type` string other than scanlineimage/tiledimage, or one that disagrees
// with its own idea of "tiled" (the version's tiled bit and a parsed `tiles` attribute), and a
// `tiles` attribute that is not 9 bytes or has level mode 3. ParseEXRHeaderFromMemory converts the
// header even when the parse failed part-way, so the first check sees whatever attributes were read
// before the failure (found by fuzz_exr: tests/corpus/found/fuzz_exr_type_*.exr). The attributes
// are walked here exactly as tinyexr's ReadAttribute walks them (same stopping rules, at most 1024)
// and every `type` attribute is renamed before tinyexr sees it, so its check can never fire; bounce
// applies the check itself. Returns the reason to refuse the file, or "".
std::string disarmTinyexrAsserts(std::vector<unsigned char>& bytes, bool versionTiled) {
  constexpr std::size_t kMaxAttributes = 1024;  // TINYEXR_MAX_HEADER_ATTRIBUTES
  std::size_t at = 8;                           // magic + version
  auto cString = [&](std::string& out) {
    const std::size_t start = at;
    while (at < bytes.size() && bytes[at] != 0) ++at;
    if (at >= bytes.size()) return false;  // no terminating NUL: tinyexr fails here
    out.assign(reinterpret_cast<const char*>(bytes.data()) + start, at - start);
    ++at;
    return true;
  };
  bool tiles = false;
  std::optional<std::string> type;  // the last non-empty one, as tinyexr keeps it
  for (std::size_t n = 0; n < kMaxAttributes && at < bytes.size() && bytes[at] != 0; ++n) {
    const std::size_t nameAt = at;
    std::string name, kind;
    if (!cString(name) || !cString(kind) || bytes.size() - at < 4) break;
    uint32_t size = 0;
    std::memcpy(&size, bytes.data() + at, 4);
    at += 4;
    if (size == 0 && kind != "string") break;
    if (size > bytes.size() - at) break;
    if (name == "tiles" && versionTiled) {
      if (size != 9)
        return "header attribute tiles has " + std::to_string(size) + " bytes (expected 9)";
      // Level mode (low 2 bits of the mode byte): one level, mipmap or ripmap; tinyexr
      // assert()s on 3 when it counts the levels (CalculateNumXLevels).
      if (const int levelMode = bytes[at + 8] & 0x3; levelMode > 2)
        return "header attribute tiles has level mode " + std::to_string(levelMode) +
               " (0 one level, 1 mipmap, 2 ripmap)";
      tiles = true;
    }
    if (name == "type") {
      const char* value = reinterpret_cast<const char*>(bytes.data()) + at;
      if (size > 0 && value[0] != 0) type = std::string(value, strnlen(value, size));
      bytes[nameAt] = 'T';  // "Type": a custom attribute tinyexr keeps and never checks
    }
    at += size;
  }
  const bool tiled = versionTiled && tiles;
  if (type && !((*type == "scanlineimage" && !tiled) || (*type == "tiledimage" && tiled)))
    return "header attribute type '" + *type + "' is not this file's kind of image";
  return {};
}

// The largest EXR bounce reads: 2^26 pixels (docs/input_limits.md, the texture limit too).
constexpr std::int64_t kMaxExrPixels = std::int64_t{1} << 26;

// tinyexr 1.0.1 sizes its offset tables from the data window, the tile size and chunkCount
// before it checks them against the file: a zero or negative tile size, or a data window whose
// width overflows int, resized a vector to a negative count (std::length_error naming no file;
// found by fuzz_exr, tests/corpus/found/fuzz_exr_tile_size_*.exr), and a huge chunkCount
// allocates gigabytes. Checked here, in 64-bit arithmetic, before any pixel is decoded.
std::string exrSizeProblem(const EXRHeader& header) {
  const EXRBox2i& box = header.data_window;
  const std::int64_t width = std::int64_t{box.max_x} - box.min_x + 1;
  const std::int64_t height = std::int64_t{box.max_y} - box.min_y + 1;
  const std::string window = "data window " + std::to_string(width) + "x" + std::to_string(height);
  if (width < 1 || height < 1) return window + " has no pixels";
  if (width * height > kMaxExrPixels)
    return window + " exceeds bounce's limit of " + std::to_string(kMaxExrPixels) + " pixels";
  if (header.tiled) {
    // A tile may be larger than the image, but not empty nor larger than the pixel limit.
    if (header.tile_size_x < 1 || header.tile_size_y < 1 ||
        std::int64_t{header.tile_size_x} * header.tile_size_y > kMaxExrPixels)
      return "tile size " + std::to_string(header.tile_size_x) + "x" +
             std::to_string(header.tile_size_y) + " is empty or exceeds " +
             std::to_string(kMaxExrPixels) + " pixels";
  } else if (header.chunk_count > height) {
    return "chunkCount " + std::to_string(header.chunk_count) + " exceeds the " +
           std::to_string(height) + " scanlines of the " + window;
  }
  return {};
}

}  // namespace

std::vector<unsigned char> encodeExr(const std::filesystem::path& path, const Image& image) {
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
  return std::vector<unsigned char>(memory, memory + size);
}

void writeExr(const std::filesystem::path& path, const Image& image) {
  writeFileAtomically(path, encodeExr(path, image));
}

Image readExr(const std::filesystem::path& path) {
  std::vector<unsigned char> bytes = readRegularFile(path);
  auto fail = [&](const std::string& reason) -> std::runtime_error {
    return std::runtime_error(path.string() + ": cannot read EXR: " + reason);
  };
  // tinyexr's lower-level calls, with the header freed on every path: its LoadEXRFromMemory
  // (1.0.1) leaks the header when the pixel data is corrupt, and would hand UINT channels over
  // as float bit patterns.
  EXRVersion version;
  if (ParseEXRVersionFromMemory(&version, bytes.data(), bytes.size()) != TINYEXR_SUCCESS)
    throw fail("not an OpenEXR file (bad magic or version)");
  if (version.multipart || version.non_image) throw fail("multi-part and deep images are not read");
  if (const std::string trigger = disarmTinyexrAsserts(bytes, version.tiled != 0); !trigger.empty())
    throw fail(trigger);
  EXRHeader header;
  InitEXRHeader(&header);
  const char* err = nullptr;
  if (ParseEXRHeaderFromMemory(&header, &version, bytes.data(), bytes.size(), &err) !=
      TINYEXR_SUCCESS) {
    FreeEXRHeader(&header);
    throw fail(takeExrError(err));
  }
  std::unique_ptr<EXRHeader, decltype(&FreeEXRHeader)> headerOwner(&header, &FreeEXRHeader);
  if (const std::string problem = exrSizeProblem(header); !problem.empty()) throw fail(problem);
  int channelOf[3] = {-1, -1, -1};  // R, G, B
  for (int c = 0; c < header.num_channels; ++c) {
    const std::string name = header.channels[c].name;
    if (header.pixel_types[c] == TINYEXR_PIXELTYPE_UINT)
      throw fail("channel '" + name +
                 "' holds UINT values; bounce reads HALF or FLOAT (linear radiance) channels");
    header.requested_pixel_types[c] = TINYEXR_PIXELTYPE_FLOAT;
    if (name == "R") channelOf[0] = c;
    if (name == "G") channelOf[1] = c;
    if (name == "B") channelOf[2] = c;
  }
  if (header.num_channels == 1) channelOf[0] = channelOf[1] = channelOf[2] = 0;  // grey
  if (channelOf[0] < 0 || channelOf[1] < 0 || channelOf[2] < 0)
    throw fail("no R, G and B channels (and not a single grey channel)");
  EXRImage exr;
  InitEXRImage(&exr);
  // On failure tinyexr has freed what it decoded (without clearing the pointers), so the image
  // is not freed again here; on some corrupt-data paths it leaks instead (docs/fuzzing.md).
  if (LoadEXRImageFromMemory(&exr, &header, bytes.data(), bytes.size(), &err) != TINYEXR_SUCCESS)
    throw fail(takeExrError(err));
  std::unique_ptr<EXRImage, decltype(&FreeEXRImage)> imageOwner(&exr, &FreeEXRImage);
  if (exr.width <= 0 || exr.height <= 0) throw fail("image has no pixels");
  Image image(exr.width, exr.height);
  auto value = [](unsigned char* const* planes, int channel, std::size_t i) {
    return reinterpret_cast<const float*>(planes[channel])[i];
  };
  if (exr.tiles == nullptr) {
    if (exr.images == nullptr) throw fail("no pixel data");
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
      for (int k = 0; k < 3; ++k) image.pixels[i][k] = value(exr.images, channelOf[k], i);
  } else {  // tiles of the full-resolution level, tile_size_x texels per stored row
    for (int t = 0; t < exr.num_tiles; ++t) {
      const EXRTile& tile = exr.tiles[t];
      if (tile.level_x != 0 || tile.level_y != 0) continue;
      for (int y = 0; y < tile.height; ++y)
        for (int x = 0; x < tile.width; ++x) {
          const int px = tile.offset_x * header.tile_size_x + x;
          const int py = tile.offset_y * header.tile_size_y + y;
          if (px < 0 || py < 0 || px >= image.width || py >= image.height) continue;
          const auto src =
              static_cast<std::size_t>(y) * static_cast<std::size_t>(header.tile_size_x) +
              static_cast<std::size_t>(x);
          glm::vec3& p =
              image.pixels[static_cast<std::size_t>(py) * static_cast<std::size_t>(image.width) +
                           static_cast<std::size_t>(px)];
          for (int k = 0; k < 3; ++k) p[k] = value(tile.images, channelOf[k], src);
        }
    }
  }
  return image;
}

// 8-bit sRGB PNG of display values in [0, 1] (already tone-mapped and encoded).
std::vector<unsigned char> encodeDisplayPng(const std::filesystem::path& path,
                                            const Image& display) {
  requireSize(path, display);
  std::vector<unsigned char> rgb;
  rgb.reserve(display.pixels.size() * 3);
  for (const glm::vec3& p : display.pixels)
    for (int c = 0; c < 3; ++c)
      rgb.push_back(static_cast<unsigned char>(std::lround(std::clamp(p[c], 0.0f, 1.0f) * 255.0f)));
  std::vector<unsigned char> encoded;
  auto append = [](void* context, void* data, int size) {
    auto* out = static_cast<std::vector<unsigned char>*>(context);
    const auto* bytes = static_cast<const unsigned char*>(data);
    out->insert(out->end(), bytes, bytes + size);
  };
  if (!stbi_write_png_to_func(append, &encoded, display.width, display.height, 3, rgb.data(),
                              display.width * 3))
    throw std::runtime_error(path.string() + ": cannot encode PNG");
  return encoded;
}

std::vector<unsigned char> encodePng(const std::filesystem::path& path, const Image& radiance,
                                     float exposureEV) {
  Image display(radiance.width, radiance.height);
  display.pixels.resize(radiance.pixels.size());
  for (std::size_t i = 0; i < radiance.pixels.size(); ++i)
    display.pixels[i] = toneMap(radiance.pixels[i], exposureEV);
  return encodeDisplayPng(path, display);
}

void writeDisplayPng(const std::filesystem::path& path, const Image& display) {
  writeFileAtomically(path, encodeDisplayPng(path, display));
}

void writePng(const std::filesystem::path& path, const Image& radiance, float exposureEV) {
  writeFileAtomically(path, encodePng(path, radiance, exposureEV));
}

std::vector<unsigned char> encodeImage(const std::filesystem::path& path, const Image& image,
                                       float exposureEV) {
  const std::string ext = path.extension().string();
  if (ext == ".exr") return encodeExr(path, image);
  if (ext == ".png") return encodePng(path, image, exposureEV);
  throw std::runtime_error(path.string() + ": unknown image extension '" + ext +
                           "' (expected .exr or .png)");
}

void writeImage(const std::filesystem::path& path, const Image& image, float exposureEV) {
  writeFileAtomically(path, encodeImage(path, image, exposureEV));
}

void writeImages(std::span<const ImageOutput> outputs) {
  std::vector<FileBytes> files;
  for (const ImageOutput& o : outputs)
    files.push_back({o.path, encodeImage(o.path, *o.image, o.exposureEV)});
  writeFilesAtomically(files);
}

}  // namespace bounce
