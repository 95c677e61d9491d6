// Writes whole files or nothing. Each file's bytes go to a temporary file in its own folder
// (".bounce-<pid>-<n>.tmp": short, so any legal target name, up to NAME_MAX = 255 bytes, still
// works), which is fsync'ed and then renamed over the target (rename is atomic within a file
// system). A failure removes the temporary files and throws std::runtime_error naming the file
// and the reason.
#pragma once

#include <filesystem>
#include <span>
#include <vector>

namespace bounce {

void writeFileAtomically(const std::filesystem::path& path, std::span<const unsigned char> bytes);

struct FileBytes {
  std::filesystem::path path;
  std::vector<unsigned char> bytes;
};

// Several outputs of one run, all or nothing: every temporary file is written and synced
// before the first rename, so a failure while writing (full disk, unwritable folder, a target
// that is a directory) leaves none of the targets changed. Only a rename itself failing after
// others succeeded (a race with another process) can leave a part; the message then names the
// files already in place.
void writeFilesAtomically(std::span<const FileBytes> files);

}  // namespace bounce
