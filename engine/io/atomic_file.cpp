#include "io/atomic_file.h"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>

namespace bounce {
namespace {

namespace fs = std::filesystem;

// A temporary name beside `path` whose length does not depend on the target's name.
fs::path temporaryBeside(const fs::path& path) {
  static std::atomic<unsigned> counter{0};
  const fs::path parent = path.has_parent_path() ? path.parent_path() : fs::path(".");
  return parent /
         (".bounce-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + ".tmp");
}

// Writes and syncs `bytes` to a new temporary file beside `path`; returns its name.
fs::path writeTemporary(const fs::path& path, std::span<const unsigned char> bytes) {
  const fs::path parent = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::error_code ec;
  fs::create_directories(parent, ec);
  if (ec) throw std::runtime_error(path.string() + ": cannot create folder: " + ec.message());
  if (fs::is_directory(path, ec))
    throw std::runtime_error(path.string() + ": cannot write: is a directory");
  const fs::path tmp = temporaryBeside(path);
  std::FILE* f = std::fopen(tmp.c_str(), "wbx");  // x: never reuse an existing file
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
  return tmp;
}

}  // namespace

void writeFileAtomically(const fs::path& path, std::span<const unsigned char> bytes) {
  const fs::path tmp = writeTemporary(path, bytes);
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw std::runtime_error(path.string() + ": cannot rename into place: " + ec.message());
  }
}

void writeFilesAtomically(std::span<const FileBytes> files) {
  std::vector<fs::path> temporaries;
  auto removeTemporaries = [&](std::size_t from) {
    std::error_code ignored;
    for (std::size_t i = from; i < temporaries.size(); ++i) fs::remove(temporaries[i], ignored);
  };
  try {
    for (const FileBytes& file : files)
      temporaries.push_back(writeTemporary(file.path, file.bytes));
  } catch (...) {
    removeTemporaries(0);
    throw;
  }
  std::string placed;
  for (std::size_t i = 0; i < files.size(); ++i) {
    std::error_code ec;
    fs::rename(temporaries[i], files[i].path, ec);
    if (ec) {
      removeTemporaries(i);
      throw std::runtime_error(files[i].path.string() +
                               ": cannot rename into place: " + ec.message() +
                               (placed.empty() ? std::string(" (nothing was written)")
                                               : " (already written: " + placed + ")"));
    }
    placed += (placed.empty() ? "" : ", ") + files[i].path.string();
  }
}

}  // namespace bounce
