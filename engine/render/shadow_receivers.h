// Where this frame's shadow maps are read (shadow_choice.h) in a GPU scene: the dynamic
// instances whose boxes meet the visible volume's box (a caster just outside the frustum may
// still throw its shadow into it) and, when asked for, points standing for the visible static
// surfaces.
#pragma once

#include "render/frustum.h"
#include "render/gpu_scene.h"
#include "render/shadow_choice.h"

namespace bounce {

// `viewPoints`: also the points of the visible part of each static, non-emitting instance's box
// (a light's mean over the air of the view would count the space around the light itself), at
// most 512 in an even spread, each weighted by the screen its cell's surface takes from `eye`
// (the camera, world metres): a cell of the 3³ grid is taken to hold surface of its largest
// face's area, so a wall near the camera counts more than a chair across the room. Where no
// grid point falls in the view (a close-up between them), the points where rays through a 5 × 5
// grid of the image first meet a visible static instance's box stand in, weighted alike.
ShadowReceivers shadowReceivers(const GpuScene& scene, const ViewVolume& view, bool viewPoints,
                                glm::vec3 eye);

}  // namespace bounce
