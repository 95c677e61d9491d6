#include "bake_folder/bake_search.h"

#include <exception>
#include <system_error>

namespace bounce {

bool BakeSearch::stale() const {
  if (bake) return false;
  for (const RefusedBake& r : refused)
    if (r.reason == RefusedBake::Reason::Stale) return true;
  return false;
}

std::filesystem::path toolDirectory() {
  std::error_code error;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
  return error ? std::filesystem::path() : exe.parent_path();
}

std::vector<std::filesystem::path> bakeCandidates(const std::filesystem::path& scenePath,
                                                  const std::filesystem::path& toolDir) {
  std::filesystem::path beside = scenePath;
  beside.replace_extension(".bake");
  std::vector<std::filesystem::path> candidates{beside};
  const std::filesystem::path folder = scenePath.parent_path().filename();
  if (!toolDir.empty() && !folder.empty())
    candidates.push_back(toolDir.parent_path() / "content" / folder /
                         (scenePath.stem().string() + ".bake"));
  return candidates;
}

BakeSearch findSceneBake(const std::filesystem::path& scenePath, const Scene& scene,
                         const std::filesystem::path& toolDir) {
  BakeSearch found;
  for (const std::filesystem::path& dir : bakeCandidates(scenePath, toolDir)) {
    std::error_code error;
    if (!std::filesystem::is_directory(dir, error)) continue;
    try {
      found.bake = readBake(dir, scene);
      found.dir = dir;
      found.notes.push_back("using the bake " + dir.string() + " (found for " +
                            scenePath.filename().string() + "; --no-bake draws without it)");
      return found;
    } catch (const std::exception& e) {
      const bool stale = dynamic_cast<const StaleBakeError*>(&e) != nullptr;
      found.refused.push_back(
          {dir, stale ? RefusedBake::Reason::Stale : RefusedBake::Reason::Unusable, e.what()});
      found.notes.push_back("not using the bake " + dir.string() + ": " + e.what() +
                            " (rebake with bounce-bake " + scenePath.string() + ")");
    }
  }
  return found;
}

}  // namespace bounce
