// Multi-bounce test scenes shared by the transport and renderer tests.
#pragma once

#include "test_scenes.h"

namespace bounce::test {

// A closed box [−1,1]³ whose every face emits `le` and reflects with albedo ρ, and a camera at
// its centre: every pixel converges to Le / (1 − ρ).
World furnace(float albedo, glm::vec3 le);
Camera furnaceCamera();

// Room [0,4]×[0,2]×[0,2] (z up) split at x = 2 by a partition of height 1.5 m; a small
// emitter lies on the left floor. The camera in the right half looks down at the right floor,
// which no emitter point sees: all its light has bounced at least once.
World corridor();
Camera corridorCamera();

// The same room with a full-height partition pierced by a vertical slit y ∈ [0.99, 1.01]
// (2 cm wide) and a ceiling emitter on the left; the camera in the right half sees light
// that came through the slit. `withPartition = false` removes the wall (open room).
World slitRooms(bool withPartition);
Camera slitCamera();

}  // namespace bounce::test
