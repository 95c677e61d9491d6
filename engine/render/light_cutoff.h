// Where a light stops being drawn: inverse-square lights have no finite range, so the light
// grid (render/light_grid.h) drops a light from a cluster only where the irradiance it can give
// any point of that cluster is below an explicit floor E_floor (W/m²). GL-free.
//
// The floor is derived from the frame's exposure: a pixel's radiance L = ρ/π · E (ρ ≤ 1) is
// displayed as D(L · 2^EV), D the filmic curve then sRGB (image/tonemap.h), whose steepest
// slope is S = max D' (6.39 per unit of exposed radiance, at x ≈ 0.0087). A light giving
// E < E_floor = π · 2^−EV · δ / S, δ = half an 8-bit code value (0.5/255), moves no displayed
// pixel by more than half a code value on its own:
//
//     E_floor(EV) = π · 2^−EV · (0.5/255) / S        (9.63·10⁻⁴ W/m² at EV 0)
//
// Bounds that keep a light wherever it may give E ≥ E_floor (each proven in the comment of the
// function that applies it):
//   point, spot  E ≤ I_max / d²               → reach d_c = sqrt(I_max / E_floor) (a sphere;
//                                               spot: also its outer cone, beyond which E = 0)
//   area         E ≤ L_max · Ω ≤ Σ_t L_t A_t / d²  (d: distance to the nearest emitter point)
//                                             → reach d_c = sqrt(Σ_t L_t A_t / E_floor) around
//                                               the light's box
//   directional  everywhere
// so a pixel's radiance loses at most ρ/π · E_floor per light left out of its cluster; the
// measured loss is far smaller (docs/renderer.md, "Light culling").
#pragma once

namespace bounce {

// Half an 8-bit code value: the display step a single culled light may not reach.
inline constexpr float kCulledLightDisplayStep = 0.5f / 255.0f;

// max over x ≥ 0 of d/dx srgbEncode(filmicCurve(x)): the display's steepest response to exposed
// radiance (found on a fine grid once; the curve is smooth).
float steepestDisplaySlope();

// E_floor (W/m²) for a frame shown at `exposureEV`, as above.
float irradianceFloorForExposure(float exposureEV);

// The distance (m) beyond which an inverse-square source of `intensity` (W/sr: a point or spot
// light's brightest channel, or Σ L·A of an area light) gives less than `floor` (W/m²).
float cutoffDistance(float intensity, float floor);

}  // namespace bounce
