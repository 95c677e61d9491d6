// What a fragment evaluates, counted where the work is done (render mode cost,
// engine/render/render_mode.h): the shading functions increment these as they go, so the
// counts are those of the same code paths that shade the full frame, not a model of them.
//   gCostLights      punctual and area lights visited (lights.glsl, area_light.glsl): the
//                    fragment's cluster list, or every light with culling off
//   gCostVpls        VPL-table lights gathered, VPLs and tree-node representatives (vpl.glsl)
//   gCostShadowTaps  shadow-map lookups (each one texture() of a depth map: a hardware 2×2
//                    comparison, a Poisson tap, an area cube's blocker or visibility fetch, a
//                    VPL cube's lookup); baked visibility texels are not shadow maps
// Included by every file that counts; forward.frag writes them out in the cost mode.
int gCostLights = 0;
int gCostVpls = 0;
int gCostShadowTaps = 0;
