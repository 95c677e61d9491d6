// Writes a whole file or nothing: the bytes go to "<path>.tmp-<pid>" in the same folder, which
// is then renamed over `path` (rename is atomic within a file system). A failure leaves no
// partial file behind and throws std::runtime_error naming the file and the reason.
#pragma once

#include <filesystem>
#include <span>

namespace bounce {

void writeFileAtomically(const std::filesystem::path& path, std::span<const unsigned char> bytes);

}  // namespace bounce
