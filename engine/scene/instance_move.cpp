#include "scene/instance_move.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace bounce {
namespace {

float coordinate(const std::string& word, const std::string& name) {
  const char* begin = word.c_str();
  char* end = nullptr;
  errno = 0;
  const float value = std::strtof(begin, &end);
  if (word.empty() || end != begin + word.size() || errno == ERANGE || !std::isfinite(value))
    throw std::invalid_argument("--move " + name + ": '" + word +
                                "' is not a finite coordinate in metres");
  return value;
}

std::string dynamicNames(const Scene& scene) {
  std::string names;
  for (const std::size_t i : dynamicInstanceHeads(scene))
    names += (names.empty() ? "'" : ", '") + scene.instances[i].name + "'";
  return names.empty() ? "none" : names;
}

}  // namespace

std::vector<InstanceMove> parseInstanceMoves(const std::vector<std::string>& words) {
  if (words.size() % 4 != 0)
    throw std::invalid_argument("--move takes four values, NAME X Y Z (metres)");
  std::vector<InstanceMove> moves;
  for (std::size_t i = 0; i < words.size(); i += 4) {
    const std::string& name = words[i];
    moves.push_back({name,
                     {coordinate(words[i + 1], name), coordinate(words[i + 2], name),
                      coordinate(words[i + 3], name)}});
  }
  return moves;
}

std::vector<std::size_t> dynamicInstancesNamed(const Scene& scene, const std::string& name) {
  std::vector<std::size_t> found;
  for (std::size_t i = 0; i < scene.instances.size(); ++i) {
    const Instance& instance = scene.instances[i];
    if (instance.name != name) continue;
    if (instance.mobility != Mobility::Dynamic)
      throw std::invalid_argument(
          scene.source + ": instance '" + name +
          "' is static (its lightmap was baked where it stands; mark its node "
          "extras.bounce.mobility = \"dynamic\" to move it); dynamic instances: " +
          dynamicNames(scene));
    found.push_back(i);
  }
  if (found.empty())
    throw std::invalid_argument(scene.source + " has no instance '" + name +
                                "'; dynamic instances: " + dynamicNames(scene));
  return found;
}

void moveInstance(Scene& scene, const InstanceMove& move) {
  for (const std::size_t i : dynamicInstancesNamed(scene, move.name))
    scene.instances[i].transform[3] = glm::vec4(move.translation, 1.0f);
}

void moveInstances(Scene& scene, const std::vector<InstanceMove>& moves) {
  for (const InstanceMove& move : moves) moveInstance(scene, move);
}

std::vector<std::size_t> dynamicInstanceHeads(const Scene& scene) {
  std::vector<std::size_t> heads;
  for (std::size_t i = 0; i < scene.instances.size(); ++i) {
    const Instance& instance = scene.instances[i];
    if (instance.mobility != Mobility::Dynamic) continue;
    bool seen = false;
    for (const std::size_t h : heads) seen = seen || scene.instances[h].name == instance.name;
    if (!seen) heads.push_back(i);
  }
  return heads;
}

}  // namespace bounce
