#include "io/regular_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace bounce {
namespace {

std::string kindOf(mode_t mode) {
  if (S_ISDIR(mode)) return "is a directory, not a file";
  if (S_ISFIFO(mode)) return "is a FIFO (named pipe), not a regular file";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device, not a regular file";
  if (S_ISSOCK(mode)) return "is a socket, not a regular file";
  return "is not a regular file";
}

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& reason) {
  throw std::runtime_error(path.string() + ": " + reason);
}

}  // namespace

std::string notRegularFileReason(const std::filesystem::path& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    return errno == ENOENT ? "file not found" : std::string("cannot open: ") + std::strerror(errno);
  if (!S_ISREG(st.st_mode)) return kindOf(st.st_mode);
  return {};
}

std::vector<unsigned char> readRegularFile(const std::filesystem::path& path,
                                           std::size_t maxBytes) {
  // Checked before open(): opening a FIFO for reading would block.
  if (const std::string reason = notRegularFileReason(path); !reason.empty()) fail(path, reason);
  // O_NONBLOCK: should the name be swapped for a FIFO after the check, open() still returns.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) fail(path, std::string("cannot open: ") + std::strerror(errno));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) fail(path, std::string("cannot stat: ") + std::strerror(errno));
  if (!S_ISREG(st.st_mode)) fail(path, kindOf(st.st_mode));
  const auto size = static_cast<std::size_t>(st.st_size);
  if (size > maxBytes) {
    fail(path, "file of " + std::to_string(size) + " bytes exceeds the limit of " +
                   std::to_string(maxBytes) + " bytes");
  }
  std::vector<unsigned char> bytes(size);
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::read(fd, bytes.data() + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail(path, std::string("read error: ") + std::strerror(errno));
    if (n == 0) break;  // shrank while reading
    done += static_cast<std::size_t>(n);
  }
  bytes.resize(done);
  return bytes;
}

}  // namespace bounce
