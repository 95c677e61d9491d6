// Placing dynamic instances: the one rule bounce-render, bounce-trace and bounce-view share, so
// the renderer and the reference path tracer see the same scene. GL-free.
//
// A move sets the world translation (metres) of every instance called `name` (a glTF node with
// several primitives flattens into several instances of one name, all with the node's
// transform); rotation and scale are kept. Only dynamic instances move: a static instance's
// lightmap (and the VPLs, which it may shadow) were baked at its file position.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace bounce {

struct InstanceMove {
  std::string name;
  glm::vec3 translation{0.0f};  // world, metres
};

// Groups of four strings NAME X Y Z (the command lines' repeatable `--move NAME X Y Z`).
// Throws std::invalid_argument on a count that is not a multiple of 4 or a coordinate that is
// not a finite number.
std::vector<InstanceMove> parseInstanceMoves(const std::vector<std::string>& words);

// The instances called `name`; throws std::invalid_argument naming the scene (Scene::source)
// and the dynamic instances it has, when there is none or one of them is static.
std::vector<std::size_t> dynamicInstancesNamed(const Scene& scene, const std::string& name);

// Sets the translation column of each named instance's transform to move.translation.
void moveInstance(Scene& scene, const InstanceMove& move);
void moveInstances(Scene& scene, const std::vector<InstanceMove>& moves);

// Indices of the dynamic instances, one per name (the first instance of each name), in scene
// order: what bounce-view's selection cycles through.
std::vector<std::size_t> dynamicInstanceHeads(const Scene& scene);

}  // namespace bounce
