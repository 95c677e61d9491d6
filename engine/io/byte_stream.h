// Little-endian byte streams for binary files (the bake folder's layout, VPL, visibility and probe
// files, the tile journal): a writer that appends, and a reader that names the file and what it
// wanted when the bytes run out. GL-free.
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "io/load_error.h"

namespace bounce {

class ByteWriter {
 public:
  void u8(uint8_t v) { bytes_.push_back(v); }
  void u16(uint16_t v) { little(v, 2); }
  void u32(uint32_t v) { little(v, 4); }
  void u64(uint64_t v) { little(v, 8); }
  void i32(int32_t v) { u32(static_cast<uint32_t>(v)); }
  void f32(float v) { u32(std::bit_cast<uint32_t>(v)); }
  void f64(double v) { u64(std::bit_cast<uint64_t>(v)); }
  void raw(const void* data, std::size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    bytes_.insert(bytes_.end(), p, p + n);
  }
  const std::vector<unsigned char>& bytes() const { return bytes_; }
  std::vector<unsigned char>&& take() { return std::move(bytes_); }

 private:
  void little(uint64_t v, int n) {
    for (int i = 0; i < n; ++i) bytes_.push_back(static_cast<unsigned char>(v >> (8 * i)));
  }
  std::vector<unsigned char> bytes_;
};

// Reads from bytes it does not own; each read throws LoadError(file, "truncated: ...") when fewer
// bytes are left than it needs.
class ByteReader {
 public:
  ByteReader(std::filesystem::path file, std::span<const unsigned char> bytes)
      : file_(std::move(file)), bytes_(bytes) {}
  void need(std::size_t n, const char* what) const {
    if (bytes_.size() - pos_ < n)
      throw LoadError(file_, "truncated: " + std::to_string(bytes_.size()) + " bytes, " + what +
                                 " needs " + std::to_string(n) + " more at byte " +
                                 std::to_string(pos_));
  }
  uint8_t u8(const char* what) { return static_cast<uint8_t>(little(1, what)); }
  uint16_t u16(const char* what) { return static_cast<uint16_t>(little(2, what)); }
  uint32_t u32(const char* what) { return static_cast<uint32_t>(little(4, what)); }
  uint64_t u64(const char* what) { return little(8, what); }
  int32_t i32(const char* what) { return static_cast<int32_t>(u32(what)); }
  float f32(const char* what) { return std::bit_cast<float>(u32(what)); }
  double f64(const char* what) { return std::bit_cast<double>(u64(what)); }
  std::span<const unsigned char> bytes(std::size_t n, const char* what) {
    need(n, what);
    const std::span<const unsigned char> out = bytes_.subspan(pos_, n);
    pos_ += n;
    return out;
  }
  bool matches(const char* data, std::size_t n) {
    return std::memcmp(bytes(n, "the magic").data(), data, n) == 0;
  }
  std::size_t position() const { return pos_; }
  std::size_t remaining() const { return bytes_.size() - pos_; }
  const std::filesystem::path& file() const { return file_; }

 private:
  uint64_t little(int n, const char* what) {
    need(static_cast<std::size_t>(n), what);
    uint64_t v = 0;
    for (int i = 0; i < n; ++i) v |= static_cast<uint64_t>(bytes_[pos_ + i]) << (8 * i);
    pos_ += static_cast<std::size_t>(n);
    return v;
  }
  std::filesystem::path file_;
  std::span<const unsigned char> bytes_;
  std::size_t pos_ = 0;
};

// FNV-1a, 64 bit: a check that catches a damaged or cut record, not an adversary.
inline uint64_t fnv1a64(std::span<const unsigned char> bytes,
                        uint64_t h = 14695981039346656037ull) {
  for (const unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

// Little-endian values at a byte offset of a buffer sized beforehand (the files of fixed-size
// records: visibility, VPLs); the caller has checked that the offset is in range.
inline void storeU16(std::vector<unsigned char>& out, std::size_t at, uint16_t v) {
  for (int i = 0; i < 2; ++i) out[at + i] = static_cast<unsigned char>(v >> (8 * i));
}
inline void storeU32(std::vector<unsigned char>& out, std::size_t at, uint32_t v) {
  for (int i = 0; i < 4; ++i) out[at + i] = static_cast<unsigned char>(v >> (8 * i));
}
inline void storeF32(std::vector<unsigned char>& out, std::size_t at, float v) {
  storeU32(out, at, std::bit_cast<uint32_t>(v));
}
inline uint16_t loadU16(std::span<const unsigned char> bytes, std::size_t at) {
  return static_cast<uint16_t>(bytes[at] | (bytes[at + 1] << 8));
}
inline uint32_t loadU32(std::span<const unsigned char> bytes, std::size_t at) {
  uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v |= static_cast<uint32_t>(bytes[at + i]) << (8 * i);
  return v;
}
inline float loadF32(std::span<const unsigned char> bytes, std::size_t at) {
  return std::bit_cast<float>(loadU32(bytes, at));
}

}  // namespace bounce
