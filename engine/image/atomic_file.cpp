#include "image/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>

namespace bounce {

void writeFileAtomically(const std::filesystem::path& path, std::span<const unsigned char> bytes) {
  namespace fs = std::filesystem;
  const fs::path parent = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::error_code ec;
  fs::create_directories(parent, ec);
  if (ec) throw std::runtime_error(path.string() + ": cannot create folder: " + ec.message());
  fs::path tmp = path;
  tmp += ".tmp-" + std::to_string(::getpid());

  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) throw std::runtime_error(path.string() + ": cannot write: " + std::strerror(errno));
  // Each step keeps the errno of the call that failed: small files only meet a full disk or a
  // size limit at the flush. fsync before the rename, so that after a crash the name never
  // points at a file whose data never reached the disk.
  int failure = 0;
  if (std::fwrite(bytes.data(), 1, bytes.size(), f) != bytes.size()) failure = errno;
  if (!failure && std::fflush(f) != 0) failure = errno;
  if (!failure && ::fsync(::fileno(f)) != 0) failure = errno;
  if (std::fclose(f) != 0 && !failure) failure = errno;
  if (failure) {
    fs::remove(tmp, ec);
    throw std::runtime_error(path.string() + ": write failed: " + std::strerror(failure));
  }
  fs::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw std::runtime_error(path.string() + ": cannot rename into place: " + ec.message());
  }
}

}  // namespace bounce
