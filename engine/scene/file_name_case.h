// Files a scene names in another letter case than the disk has them. OBJ/MTL files written on
// Windows or macOS (whose file systems ignore case) name `map_Kd SP_LUK.JPG` for `sp_luk.JPG`, or
// `Textures\\wall.png` with a backslash: on Linux the name as written is not found. GL-free.
#pragma once

#include <filesystem>
#include <string>

namespace bounce {

// `folder / name` when that exists. Otherwise the one existing path below `folder` that equals it
// component by component ignoring ASCII letter case (with `\` read as a separator), or an empty
// path when there is none, or several (`a.png` and `A.png` beside each other): a guess between
// two files would pick the wrong texture silently.
std::filesystem::path findIgnoringCase(const std::filesystem::path& folder,
                                       const std::string& name);

}  // namespace bounce
