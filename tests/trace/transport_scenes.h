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

// The slit rooms with black (ρ = 0) walls, partition, ceiling and emitter: only the floor
// (the box's first mesh) reflects, with albedo `floorAlbedo`. A floor point sees no other
// reflecting surface, so its radiance is ρ·Le·F with F the form factor of the part of the
// emitter visible through the slit: a closed-form reference.
World blackSlitRooms(bool withPartition, float floorAlbedo);
// Straight down from (3, 1, 1.5), 60°: the view holds only the right room's floor.
Camera slitFloorCamera();
// Geometry of the slit rooms (the floats the scenes are built from).
constexpr float kSlitY0 = 0.99f, kSlitY1 = 1.01f, kSlitX = 2.0f;
constexpr float kSlitLightX0 = 0.5f, kSlitLightX1 = 1.5f, kSlitLightY0 = 0.5f, kSlitLightY1 = 1.5f,
                kSlitLightZ = 1.99f, kSlitLightLe = 10.0f;

}  // namespace bounce::test
