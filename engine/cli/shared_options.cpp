#include "cli/shared_options.h"

namespace bounce {

void addSceneOption(CLI::App& app, SharedOptions& o) {
  app.add_option("scene", o.scene, "scene file (.gltf, .glb, .obj, or a .json wrapper)")
      ->required();
}

void addCameraOption(CLI::App& app, SharedOptions& o) {
  app.add_option("--camera", o.camera, "camera name (default: the scene's first camera)");
}

void addSizeOptions(CLI::App& app, SharedOptions& o, int minSide, const std::string& what,
                    const std::string& defaults) {
  const std::string tail = defaults.empty() ? "" : " (" + defaults + ")";
  app.add_option("--width", o.width, what + " width in pixels" + tail)
      ->check(CLI::Range(minSide, kMaxImageSide));
  app.add_option("--height", o.height, what + " height in pixels" + tail)
      ->check(CLI::Range(minSide, kMaxImageSide));
}

void addExposureOption(CLI::App& app, SharedOptions& o) {
  app.add_option("--exposure", o.exposure,
                 "exposure in EV of what is tone-mapped (PNG, the window): radiance x 2^EV "
                 "(default 0)");
}

void addBakeOptions(CLI::App& app, SharedOptions& o) {
  app.add_option("--bake", o.bake,
                 "bake folder (bounce-bake's output) for this scene: adds its baked light "
                 "(default: <scene>.bake beside the scene, else the build step's bake of a "
                 "content scene, when one exists and matches the scene)");
  app.add_flag("--no-bake", o.noBake, "draw without baked light, even where a bake exists")
      ->excludes("--bake");
}

void addModeOption(CLI::App& app, SharedOptions& o, const std::vector<std::string>& modes,
                   const std::string& lead) {
  app.add_option(
         "--mode", o.mode,
         lead +
             ": full (direct + baked indirect; the default with a bake), direct (real-time "
             "direct light only; the default without), indirect (only the baked rho/pi*E), "
             "lightmap (E/pi: the baked irradiance on a white surface), charts (lightmap charts "
             "and texels), vpl (indirect light of every surface from the bake's VPLs, "
             "rho/pi*E_vpl), vpl-clamp (red: the VPLs' E/pi on a white surface, green: what "
             "their clamp removed), error (each texel's estimated relative error: blue 0, green "
             "at the bake's target, red at twice it or more), validity (green: texels with "
             "samples of their own, orange: filled from their neighbours, dark blue: padding), "
             "texel-density (lightmap texels per metre against the bake's texel size: blue half "
             "or less, green equal, red twice or more, over a checker of texels), cascades (the "
             "directional light's shadow cascade: red, green, blue, yellow from near to far, "
             "cross-faded where they blend; needs no bake), cost (what each pixel evaluated, "
             "shaded as full: the lights, VPLs or shadow-map taps, --cost-count, in false colour "
             "with a legend bar; bounce-render's EXR holds the raw counts, R lights, G VPLs, B "
             "taps; needs no bake)")
      ->check(CLI::IsMember(modes));
}

void addMsaaOption(CLI::App& app, SharedOptions& o) {
  app.add_option("--msaa", o.msaa,
                 "samples per pixel (multisample anti-aliasing; the radiance is averaged over "
                 "each pixel before tone mapping, a box filter as bounce-trace's); 1 turns it "
                 "off (default 4)")
      ->check(CLI::Range(1, 64));
}

void addCostViewOptions(CLI::App& app, SharedOptions& o, const std::string& scaleDefault) {
  app.add_option("--cost-count", o.costCount,
                 "mode cost: the count shown in false colour, lights, vpls or taps (default "
                 "vpls)")
      ->check(CLI::IsMember({"lights", "vpls", "taps"}));
  app.add_option("--cost-max", o.costMax,
                 "mode cost: the count at the red end of the scale (default: " + scaleDefault + ")")
      ->check(CLI::PositiveNumber);
}

void addDynamicVplsOption(CLI::App& app, SharedOptions& o) {
  app.add_option("--dynamic-vpls", o.dynamicVpls,
                 "VPLs with dynamic instances in the scene: retrace (default: the light paths "
                 "traced again with them in place, so they shadow the room and reflect light "
                 "into it) or cut (the bake's VPLs, their paths cut where the dynamic instances "
                 "block them; cheaper, misses the light those reflect)")
      ->check(CLI::IsMember({"retrace", "cut"}));
}

void addPathTracingOptions(CLI::App& app, SharedOptions& o) {
  app.add_option("--max-depth", o.maxDepth, "most diffuse reflections along a path")
      ->check(CLI::Range(0, 100000));
  app.add_option("--seed", o.seed,
                 "sampler seed (the same seed gives the same result at any thread count)");
  app.add_option("--threads", o.threads, "worker threads (0: all cores)")
      ->check(CLI::Range(0, 1024));
  app.add_option("--backend", o.backend, "ray kernel: embree or bvh")
      ->check(CLI::IsMember({"embree", "bvh"}));
  app.add_option("--light-choice", o.lightChoice,
                 "how next-event estimation picks its one light per path vertex: place (by a "
                 "bound of what each light brings there) or power (by power alone)")
      ->check([](const std::string& name) {
        return parseLightChoice(name) ? std::string() : name + " is not place or power";
      });
}

}  // namespace bounce
