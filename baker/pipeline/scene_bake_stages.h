// The scene bake's stages, one function each, in the order bakeScene (scene_bake.h) runs them:
//   1 atlas             atlasStage          scene_atlas_stage.cpp
//   2 ray kernel        rayKernelStage      scene_bake.cpp
//   3–7 lightmap        lightmapStages      scene_lightmap_stage.cpp (coverage, leak guard,
//                                           irradiance, light visibility, filters)
//   8 VPLs              vplStage            scene_vpl_stage.cpp
//   the folder          lightmapFolder      scene_bake_folder.cpp (files and bake.json)
//   9 probes            probeStage          probe_stage.cpp (instances without a lightmap)
// Each begins its stages on the plan (so an observer sees them and can cancel), writes what it
// makes into the SceneBake (its files, its part of bake.json, its seconds under `measured`) and
// returns what later stages need. Internal to baker/pipeline; GL-free.
#pragma once

#include <memory>

namespace bounce {

// The stages' names on the plan that are not the lightmap's (bake/lightmap_bake.h names those).
inline constexpr char kStageAtlas[] = "atlas";
inline constexpr char kStageRayKernel[] = "ray kernel";
inline constexpr char kStageVpls[] = "VPLs";

struct Atlas;
struct LightmapBake;
struct LightmapLayout;
struct Scene;
struct SceneBake;
struct SceneBakeSettings;
struct WorldGeometry;
class RayKernel;
class StagePlan;

// What the stages after the atlas trace in: the static scene (dynamic instances left out of
// the whole bake), its flattened geometry and the ray kernel over it.
struct StaticGeometry {
  StaticGeometry();
  StaticGeometry(StaticGeometry&&) noexcept;
  ~StaticGeometry();
  std::unique_ptr<Scene> scene;
  std::unique_ptr<WorldGeometry> geometry;
  std::unique_ptr<RayKernel> kernel;
};

// 1: the atlas; its notes and the memory estimate into `result`. Throws std::runtime_error for
// a scene with nothing static, BakeOverMemoryBudget for an estimate over settings.maxMemory.
Atlas atlasStage(const Scene& scene, const SceneBakeSettings& settings, const StagePlan& plan,
                 SceneBake& result);

// 2: the static scene and its ray kernel.
StaticGeometry rayKernelStage(const Scene& scene, const SceneBakeSettings& settings,
                              const StagePlan& plan, SceneBake& result);

// 3–7: the lightmap (bake/lightmap_bake.h) over the tiles of tile_sources.h; the tile counts
// and the notes of a resume into `result`.
LightmapBake lightmapStages(const Scene& scene, const StaticGeometry& statics, const Atlas& atlas,
                            const SceneBakeSettings& settings, const StagePlan& plan,
                            SceneBake& result);

// 8: the VPLs (vpl/vpl_generate.h) into the folder and bake.json's "vpls", when settings.vpls.
void vplStage(const StaticGeometry& statics, const SceneBakeSettings& settings,
              const StagePlan& plan, SceneBake& result);

// `layout` (instance indices into `scene`) renumbered for staticScene(scene)
// (scene/static_scene.h): the lightmap bake runs in the static scene, the folder keeps the file
// scene's numbering. Every region is a static instance's (the atlas lays out no other).
LightmapLayout staticLayout(const Scene& scene, LightmapLayout layout);

// The lightmap's files (layout, lightmap, error map, visibility) and bake.json but for the
// VPLs' part and the total seconds.
void lightmapFolder(const Scene& scene, const SceneBakeSettings& settings, const Atlas& atlas,
                    const LightmapBake& bake, const StaticGeometry& statics, SceneBake& result);

// 9: the irradiance probes of the static instances the atlas left without a lightmap region
// (probe_stage.h) into the folder, bake.json's "probes" and the notes, when there are any.
// Their paths end at `bake`'s delivered map after one reflection (probe_stage.h).
void probeStage(const Scene& scene, const StaticGeometry& statics, const Atlas& atlas,
                const LightmapBake& bake, const SceneBakeSettings& settings, const StagePlan& plan,
                SceneBake& result);

}  // namespace bounce
