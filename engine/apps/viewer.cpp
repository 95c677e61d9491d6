#include "viewer.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "bake_folder/bake_facts.h"
#include "bake_folder/bake_folder.h"
#include "bake_folder/bake_search.h"
#include "cli/viewer_script_replay.h"
#include "gl/gpu_pass_timers.h"
#include "gl/panel_layer.h"
#include "gl/render_target.h"
#include "gl/shader.h"
#include "gl/window.h"
#include "image/image_io.h"
#include "render/area_shadow_budget.h"
#include "render/fly_camera.h"
#include "render/forward_renderer.h"
#include "render/punctual_shadow_budget.h"
#include "render/reference_compare_pass.h"
#include "render/tonemap_pass.h"
#include "render/view.h"
#include "render/vpl_pass.h"
#include "scene/dynamic_selection.h"
#include "scene/framing.h"
#include "viewer_input.h"
#include "viewer_panel.h"
#include "viewer_rebake.h"
#include "vpl/vpl_retrace.h"

namespace bounce {
namespace {

using Clock = std::chrono::steady_clock;

// Writes the radiance as `path` (by extension); for F12, both PNG and EXR.
void save(const bounce::Image& radiance, const std::string& path, float exposure) {
  bounce::writeImage(path, radiance, exposure);
  std::fprintf(stderr, "bounce-view: wrote %s\n", path.c_str());
}

// The bake in use: where it was read from and what was said while looking for it.
struct LoadedBake {
  std::optional<bounce::Bake> bake;
  std::filesystem::path dir;
  std::vector<std::string> notes;
  bool stale = false;  // the scene's bake was found but no longer matches it (BakeSearch::stale)
};

// With a bake's VPLs and --dynamic-vpls retrace, moving a dynamic instance traces them again
// with it in place (vpl/vpl_retrace.h).
bounce::RendererSettings rendererSettings(const ViewerOptions& options, const bounce::Scene& scene,
                                          const std::optional<bounce::Bake>& bake,
                                          bounce::RenderMode mode) {
  bounce::RendererSettings settings;
  settings.mode = mode;
  if (bake && bake->vpls && options.shared.dynamicVpls == "retrace")
    settings.vplTracer = bounce::placedVplTracer(scene, *bake);
  return settings;
}

class Viewer final : private bounce::ScriptActions {
 public:
  Viewer(const ViewerOptions& options, bounce::Scene scene, LoadedBake loaded,
         bounce::RenderMode mode)
      : options_(options),
        scene_(std::move(scene)),
        bake_(std::move(loaded.bake)),
        bakeDir_(std::move(loaded.dir)),
        bakeNotes_(std::move(loaded.notes)),
        window_("bounce-view", options.shared.width, options.shared.height),
        renderer_(scene_, bounce::gl::shaderDirectory(),
                  rendererSettings(options, scene_, bake_, mode), bake_ ? &*bake_ : nullptr),
        tonemap_(bounce::gl::shaderDirectory()),
        compare_(bounce::gl::shaderDirectory()),
        selection_(scene_),
        objectSpeed_(bounce::objectSpeed(scene_)),
        exposure_(options.shared.exposure),
        script_(options.scriptFile, options.script) {
    std::fprintf(stderr, "bounce-view: OpenGL %s, %s\n", window_.version().c_str(),
                 window_.renderer().c_str());
    for (const std::string& warning : scene_.warnings)
      std::fprintf(stderr, "bounce-view: warning: %s\n", warning.c_str());
    for (const std::string& warning : renderer_.warnings())
      std::fprintf(stderr, "bounce-view: warning: %s\n", warning.c_str());
    cameras_ = scene_.cameras;
    const glm::ivec2 size = window_.framebufferSize();
    const float aspect = static_cast<float>(size.x) / static_cast<float>(std::max(size.y, 1));
    if (cameras_.empty()) {
      std::fprintf(stderr, "bounce-view: warning: the scene has no camera; framing its bounds\n");
      cameras_.push_back(bounce::frameBounds(bounce::sceneBounds(scene_), aspect));
    }
    const bounce::Bounds bounds = bounce::sceneBounds(scene_);
    speed_ = std::max(0.25f * glm::length(bounds.hi - bounds.lo), 0.1f);  // m/s
    try {
      panel_.emplace(window_);
      panelShown_ = !options.noPanel;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "bounce-view: warning: no panel (%s); the keys still work\n", e.what());
    }
    if (bake_) bakeLines_ = bounce::bakeFactLines(bounce::bakeFacts(*bake_, bakeDir_));
    bakeStale_ = loaded.stale;
    if (bakeStale_)
      std::fprintf(stderr,
                   "bounce-view: lighting needs to be rebuilt: the scene's bake is stale (the "
                   "panel's 'bake now' or the script's rebake re-bakes it)\n");
    select(options.shared.camera.empty() ? 0 : scene_.findCamera(options.shared.camera));
    if (!options.reference.empty()) {
      referenceView_ = *bounce::parseReferenceView(options.compare);  // CLI11 checked
      loadReference(options.reference);
    }
  }

  int run() {
    auto last = Clock::now();
    auto titleShown = last;
    double frameMs = 0.0, steadyMs = 0.0;
    for (int frame = 0; !window_.shouldClose(); ++frame) {
      window_.pollEvents();
      const auto now = Clock::now();
      const float dt = std::chrono::duration<float>(now - last).count();
      const double ms = std::chrono::duration<double, std::milli>(now - last).count();
      frameMs = frame < 2 ? ms : 0.9 * frameMs + 0.1 * ms;  // smoothed for reading
      last = now;
      if (frame >= 2) steadyMs += ms;  // the first frames include llvmpipe's shader JIT
      applyInput(dt);
      script_.beforeFrame(*this);
      takeRebakedPass();
      draw();
      // The GPU time of the newest frame whose pass timers are in (a frame or two late).
      times_.add(ms, renderer_.profile().lastGpuFrame());
      // The panel's table: each pass over the last 60 frames.
      if (frame % 60 == 59) {
        passTimes_ = renderer_.profile().gpuPasses();
        cpuTimes_ = renderer_.profile().cpu();
        renderer_.clearProfile(false);
      }
      if (panel_ && panelShown_) drawPanel();
      const bool scriptEnded = !script_.empty() && script_.afterFrame(*this);
      if (scriptEnded || (options_.frames > 0 && frame + 1 >= options_.frames)) {
        if (!options_.screenshot.empty()) save(shown().read(), options_.screenshot, exposure_);
        if (!options_.windowShot.empty()) saveWindow(options_.windowShot);
        std::fprintf(stderr,
                     "bounce-view: %d frames; mean frame time after the first two %.1f ms\n",
                     frame + 1, frame >= 2 ? steadyMs / (frame - 1) : ms);
        return 0;
      }
      if (saveRequested_) saveScreenshot();
      window_.swapBuffers();
      if (now - titleShown > std::chrono::milliseconds(250)) {
        titleShown = now;
        char object[160] = "";
        if (!selection_.empty()) {
          const glm::vec3 at = selection_.translation(scene_);
          std::snprintf(object, sizeof object,
                        " — moving '%s' (G: next of %zu) at (%.3f, %.3f, %.3f) m",
                        selection_.name(scene_).c_str(), selection_.count(), at.x, at.y, at.z);
        }
        char title[512];
        std::snprintf(title, sizeof title,
                      "bounce-view — %s — camera '%s' — %s — %.1f ms — %.2f m/s — %+.1f EV%s",
                      options_.shared.scene.c_str(), cameras_[cameraIndex_].name.c_str(),
                      std::string(bounce::renderModeName(renderer_.settings().mode)).c_str(),
                      frameMs, speed_, exposure_, object);
        window_.setTitle(title);
      }
    }
    return 0;
  }

 private:
  void select(std::size_t index) {
    cameraIndex_ = index;
    fly_.emplace(cameras_[index]);
  }

  // The next of availableModes() (the order M steps through them): without a bake direct and
  // cascades; the VPL modes only when the bake has VPLs, error and validity only with error.exr.
  void nextMode() {
    const std::vector<bounce::RenderMode> modes = availableModes();
    const auto at = std::find(modes.begin(), modes.end(), renderer_.settings().mode);
    if (modes.empty()) return;
    setMode(at == modes.end() || at + 1 == modes.end() ? modes.front() : *(at + 1));
  }

  void toggleCharts() {
    if (!renderer_.hasBake()) return;
    const bounce::RenderMode mode = renderer_.settings().mode;
    if (mode != bounce::RenderMode::Charts) modeBeforeCharts_ = mode;
    setMode(mode == bounce::RenderMode::Charts ? modeBeforeCharts_ : bounce::RenderMode::Charts);
  }

  void setMode(bounce::RenderMode mode) {
    renderer_.setMode(mode);
    std::fprintf(stderr, "bounce-view: mode %s%s\n",
                 std::string(bounce::renderModeName(mode)).c_str(),
                 mode == bounce::RenderMode::Lightmap
                     ? " (pixels are E/pi: the baked irradiance on a white surface)"
                 : mode == bounce::RenderMode::VplClamp
                     ? " (red: the VPLs' E/pi on a white surface; green: what their clamp removed)"
                 : mode == bounce::RenderMode::Validity
                     ? " (green: texels with samples of their own; orange: filled from their "
                       "neighbours; dark blue: padding)"
                 : mode == bounce::RenderMode::Error
                     ? " (each texel's estimated relative error: blue 0, green at the bake's "
                       "target, red at twice it or more, dark grey none)"
                 : mode == bounce::RenderMode::TexelDensity
                     ? " (lightmap texels per metre against the bake's texel size: blue half or "
                       "less, green equal, red twice or more; checker: one square per texel)"
                 : mode == bounce::RenderMode::Cascades
                     ? " (the directional light's shadow cascade: red, green, blue, yellow from "
                       "near to far; grey: no shadowed directional light)"
                     : "");
  }

  void saveWindow(const std::string& path) {
    const glm::ivec2 size = glm::max(window_.framebufferSize(), glm::ivec2(1));
    const bounce::Image shown = bounce::gl::readWindowPixels(size.x, size.y);
    if (std::filesystem::path(path).extension() == ".png")
      bounce::writeDisplayPng(path, shown);
    else
      bounce::writeExr(path, shown);
    std::fprintf(stderr, "bounce-view: wrote %s\n", path.c_str());
  }

  // ScriptActions (cli/viewer_script_replay.h): what a --script command does.
  void selectCamera(const std::string& name) override { select(scene_.findCamera(name)); }
  void lookFrom(const glm::vec3& position, const glm::vec3& target) override {
    bounce::Camera camera = fly_->camera();
    camera.cameraToWorld = glm::inverse(glm::lookAt(position, target, glm::vec3(0, 1, 0)));
    fly_.emplace(camera);
  }
  void setModeNamed(const std::string& mode) override { setMode(*bounce::parseRenderMode(mode)); }
  void setExposure(float ev) override { exposure_ = ev; }
  void showPanel(bool on) override { panelShown_ = on && panel_.has_value(); }
  void startRebake() override { rebake_.start(scene_, options_.shared.scene, lightsEdited_); }
  void cancelRebake() override { rebake_.cancel(); }
  void setLightField(const std::string& name, const std::string& field,
                     const glm::vec3& value) override {
    const std::size_t index = lightNamed(name);
    bounce::Light light = scene_.lights[index];
    glm::vec3& power =
        light.type == bounce::LightType::Directional ? light.irradiance : light.intensity;
    if (field == "intensity") power = value;
    if (field == "position") light.position = value;
    if (field == "direction") light.direction = glm::normalize(value);
    editLight(index, light);
  }
  void setVplPaths(uint64_t paths) override {
    requireVpls();
    selectVpls(paths, renderer_.vplSelection().clampDistance);
  }
  void setVplClamp(float distance) override {
    requireVpls();
    selectVpls(renderer_.vplSelection().paths, distance);
  }
  void setComparison(const std::string& how) override {
    setReferenceView(*bounce::parseReferenceView(how));
  }
  void capture(const std::string& file) override { save(shown().read(), file, exposure_); }
  void captureWindow(const std::string& file) override { saveWindow(file); }
  bool rebakePending() override { return rebake_.pending(); }

  void requireVpls() const {
    if (!renderer_.hasVpls()) throw std::runtime_error("no VPLs to choose from: the bake has none");
  }

  // The panel goes over the tone-mapped frame in the window's framebuffer, after the frame was
  // drawn and before a capture is read from the target: captures never hold it.
  void drawPanel() {
    bounce::ViewerPanelView view;
    view.scene = options_.shared.scene;
    view.bakeLines = bakeLines_;
    view.bakeNotes = bakeNotes_;
    view.modes = availableModes();
    view.mode = renderer_.settings().mode;
    view.exposure = exposure_;
    view.msaa = options_.shared.msaa;
    for (const bounce::Camera& camera : cameras_) view.cameras.push_back(camera.name);
    view.camera = cameraIndex_;
    for (const std::optional<bounce::FlyCamera>& bookmark : bookmarks_)
      view.bookmarks.push_back(bookmark.has_value());
    view.referenceFile = referenceFile_;
    view.referenceView = referenceView_;
    if (renderer_.hasVpls()) {
      const bounce::ForwardRenderer::VplSelection s = renderer_.vplSelection();
      view.vpls = bounce::PanelVpls{s.paths, s.totalPaths, s.vplCount, s.clampDistance,
                                    s.bakeClampDistance};
    }
    view.object = selection_.empty() ? "" : selection_.name(scene_);
    view.objectCount = selection_.count();
    view.lights = &scene_.lights;
    view.bakeStale = bakeStale_;
    if (const auto cost = costDisplay())
      view.costLegend = bounce::describeCostLegend(cost->count, cost->scaleMax);
    view.times = &times_;
    view.passTimes = &passTimes_;
    view.cpuTimes = &cpuTimes_;
    view.rebaking = rebake_.running();
    view.rebakeStatus = rebake_.status();
    view.rebakeFraction = rebake_.fraction();
    panel_->beginFrame();
    const bounce::ViewerPanelRequests requests = bounce::drawViewerPanel(view);
    panel_->endFrame();
    if (requests.mode) setMode(*requests.mode);
    if (requests.exposure) exposure_ = *requests.exposure;
    if (requests.camera) select(*requests.camera);
    if (requests.saveBookmark) saveBookmark(*requests.saveBookmark);
    if (requests.goToBookmark && bookmarks_.at(*requests.goToBookmark))
      goToBookmark(*requests.goToBookmark);
    if (requests.loadReference) try {
        loadReference(*requests.loadReference);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "bounce-view: error: %s\n", e.what());  // keep viewing
      }
    if (requests.referenceView && compare_.hasReference()) referenceView_ = *requests.referenceView;
    if (requests.vplSelection) try {
        selectVpls(requests.vplSelection->first, requests.vplSelection->second);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "bounce-view: %s\n", e.what());  // keep the VPLs drawn
      }
    if (requests.nextObject) selectNextObject();
    if (requests.screenshot) saveRequested_ = true;
    for (const auto& [index, light] : requests.lightEdits) editLight(index, light);
    if (requests.rebake) startRebake();
    if (requests.cancelRebake) rebake_.cancel();
  }

  std::size_t lightNamed(const std::string& name) const {
    for (std::size_t i = 0; i < scene_.lights.size(); ++i)
      if (scene_.lights[i].name == name) return i;
    throw std::runtime_error("no punctual light named '" + name + "'");
  }

  // A light edited in the panel or a script: drawn so at once; the baked light, which holds the
  // old light's indirect (and, for a baked-only light, direct) light, is stale until a re-bake.
  void editLight(std::size_t index, const bounce::Light& light) {
    scene_.lights.at(index) = light;
    renderer_.setLight(index, light);
    lightsEdited_ = true;
    if (bake_ && !bakeStale_) {
      bakeStale_ = true;
      bakeNotes_.push_back(
          "the baked light is stale: a light changed since the bake (re-bake "
          "to update it; the scene file is not changed)");
      std::fprintf(stderr, "bounce-view: %s\n", bakeNotes_.back().c_str());
    }
  }

  // Draws with a pass of the re-bake (viewer_rebake.h) as soon as it is done: the preview, then
  // the final bake.
  void takeRebakedPass() {
    std::optional<bounce::RebakedPass> pass = rebake_.take();
    if (!pass) return;
    const bool hadBake = renderer_.hasBake();
    bake_ = std::move(pass->bake);
    renderer_.setBake(*bake_);
    if (!hadBake && renderer_.settings().mode == bounce::RenderMode::Direct)
      setMode(bounce::RenderMode::Full);
    bakeDir_ = pass->writtenTo;
    bakeLines_ = std::move(pass->factLines);
    bakeNotes_ = {pass->note};
    bakeStale_ = false;
  }

  // The modes this bake allows, in the order M steps through them.
  std::vector<bounce::RenderMode> availableModes() const {
    std::vector<bounce::RenderMode> modes;
    for (const std::string& name : bounce::renderModeNames()) {
      const bounce::RenderMode mode = *bounce::parseRenderMode(name);
      if (bounce::renderModeNeedsBake(mode) && !renderer_.hasBake()) continue;
      if (bounce::renderModeNeedsVpls(mode) && !renderer_.hasVpls()) continue;
      if (bounce::renderModeNeedsErrorMap(mode) && !renderer_.hasErrorMap()) continue;
      modes.push_back(mode);
    }
    return modes;
  }

  // The keys and the mouse (viewer_input.h), applied.
  void applyInput(float dt) {
    const bool panelOn = panel_ && panelShown_;
    const bounce::ViewerInput in = controls_.read(window_, panelOn && panel_->wantsKeyboard(),
                                                  panelOn && panel_->wantsMouse());
    if (in.togglePanel && panel_) panelShown_ = !panelShown_;
    if (in.quit) window_.requestClose();
    if (in.nextCamera) select((cameraIndex_ + 1) % cameras_.size());
    if (in.camera && *in.camera < cameras_.size()) select(*in.camera);
    speed_ *= in.speedFactor;
    if (in.screenshot) saveRequested_ = true;
    exposure_ += in.exposureStep;
    if (in.nextMode) nextMode();
    if (in.toggleCharts) toggleCharts();
    if (in.nextObject) selectNextObject();
    if (in.saveBookmark) saveBookmark(*in.saveBookmark);
    if (in.goToBookmark && bookmarks_[*in.goToBookmark]) goToBookmark(*in.goToBookmark);
    if (in.goToBookmark && !bookmarks_[*in.goToBookmark])
      std::fprintf(stderr, "bounce-view: bookmark %zu is empty (Shift+F%zu saves it)\n",
                   *in.goToBookmark + 1, *in.goToBookmark + 1);
    fly_->move(in.fly * speed_ * in.boost * dt);
    moveObject(in.object * objectSpeed_ * in.boost * dt);
    if (in.turn) fly_->turn(in.turn->x, in.turn->y);
  }

  // Camera bookmarks (F1..F4 go, Shift+F1..F4 save; the panel; the script's bookmark): the fly
  // camera as it stands (position, heading, lens), for this session; going back restores that
  // state itself, so the frame is the one drawn when it was saved.
  void saveBookmark(std::size_t slot) override {
    bookmarks_.at(slot) = *fly_;
    const glm::vec3 at = bookmarks_[slot]->position();
    std::fprintf(stderr, "bounce-view: bookmark %zu saved at (%.3f, %.3f, %.3f) m\n", slot + 1,
                 at.x, at.y, at.z);
  }

  void goToBookmark(std::size_t slot) override {
    if (!bookmarks_.at(slot))
      throw std::runtime_error("bookmark " + std::to_string(slot + 1) + " is empty");
    fly_ = *bookmarks_[slot];
  }

  // The VPLs of the bake's first `paths` light paths at clamp distance r (panel, script).
  void selectVpls(uint64_t paths, float clampDistance) {
    renderer_.setVplSelection(paths, clampDistance);
    const bounce::ForwardRenderer::VplSelection s = renderer_.vplSelection();
    std::fprintf(
        stderr, "bounce-view: VPLs of %llu of %llu light paths (%zu VPLs), clamp r = %.4g m\n",
        static_cast<unsigned long long>(s.paths), static_cast<unsigned long long>(s.totalPaths),
        s.vplCount, static_cast<double>(s.clampDistance));
  }

  void selectNextObject() {
    selection_.selectNext();
    if (!selection_.empty())
      std::fprintf(stderr, "bounce-view: moving '%s'\n", selection_.name(scene_).c_str());
  }

  // `screen`: (right, up, away from the camera) in metres, moved along the world axes nearest
  // to the camera's right, up and forward.
  void moveObject(const glm::vec3& screen) {
    if (selection_.empty() || screen == glm::vec3(0.0f)) return;
    const bounce::Camera camera = fly_->camera();
    const glm::vec3 right = glm::vec3(camera.cameraToWorld[0]);
    const glm::vec3 delta = bounce::nearestAxis(right) * screen.x +
                            bounce::nearestAxis(camera.up()) * screen.y +
                            bounce::nearestAxis(camera.forward()) * screen.z;
    for (const std::size_t i : selection_.move(scene_, delta))
      renderer_.setInstanceTransform(i, scene_.instances[i].transform);
  }

  // The area-light cube budget, logged whenever its choice changes (the camera or a dynamic
  // instance moved): which lights have a cube, what the rest bring.
  void reportAreaShadowChoice() {
    const bounce::ShadowChoice& choice = renderer_.areaShadowChoice();
    if (renderer_.areaShadowSlots() == 0 ||
        (choice.lights == reportedLights_ && choice.unshadowed == reportedUnshadowed_))
      return;
    reportedLights_ = choice.lights;
    reportedUnshadowed_ = choice.unshadowed;
    std::fprintf(stderr, "bounce-view: %s\n",
                 bounce::describeAreaShadowChoice(choice, renderer_.areaShadowSlots()).c_str());
  }

  // The punctual lights' maps, logged whenever a light gains or loses one (a kind with more
  // lights than maps gives them to those that bring the most to the view).
  void reportPunctualShadowMaps() {
    const std::span<const int> slots = renderer_.punctualShadowSlots();
    std::vector<bool> now;
    for (const int slot : slots) now.push_back(slot >= 0);
    // Logged on every change, but not at the start when every light has a map.
    const bool allMapped = std::find(now.begin(), now.end(), false) == now.end();
    if (now == reportedMaps_ || (reportedMaps_.empty() && allMapped)) return;
    reportedMaps_ = now;
    std::fprintf(stderr, "bounce-view: %s\n",
                 bounce::describePunctualShadowMaps(scene_.lights, slots).c_str());
  }

  void draw() {
    const glm::ivec2 size = glm::max(window_.framebufferSize(), glm::ivec2(1));
    if (!target_ || target_->width() != size.x || target_->height() != size.y)
      target_ = std::make_unique<bounce::gl::RenderTarget>(size.x, size.y, options_.shared.msaa);
    // The light cut-off follows the exposure shown (render/light_cutoff.h).
    const float floor = bounce::irradianceFloorForExposure(exposure_);
    if (renderer_.settings().lightCulling.irradianceFloor != floor) {
      bounce::LightCullingSettings culling = renderer_.settings().lightCulling;
      culling.irradianceFloor = floor;
      renderer_.setLightCulling(culling);
    }
    renderer_.render(fly_->camera(), *target_);
    reportAreaShadowChoice();
    reportPunctualShadowMaps();
    if (comparing()) {
      if (!compared_ || compared_->width() != size.x || compared_->height() != size.y)
        compared_ = std::make_unique<bounce::gl::RenderTarget>(size.x, size.y);
      compare_.draw(target_->color(), *compared_, referenceView_);
    }
    bounce::gl::bindDefaultFramebuffer(size.x, size.y);
    const bounce::gl::GpuPassTimers::Scope timed(&renderer_.gpuTimers(), "tone map");
    tonemap_.draw(shown().color(), exposure_, costDisplay());
  }

  // The cost view's count and scale (none in the other modes): --cost-count, --cost-max, else
  // 1, 2 or 5 x 10^k at or above what a pixel can reach of it (lights: all of them; VPLs: the
  // largest lightcut; taps: 64, four 16-tap lights).
  std::optional<bounce::TonemapPass::CostDisplay> costDisplay() const {
    if (renderer_.settings().mode != bounce::RenderMode::Cost) return std::nullopt;
    const bounce::CostCount count =
        *bounce::parseCostCount(options_.shared.costCount);  // CLI11 checked
    float bound = 64.0f;
    if (count == bounce::CostCount::Lights)
      bound = static_cast<float>(scene_.lights.size() + renderer_.areaLightCount());
    if (count == bounce::CostCount::Vpls) {
      // The largest lightcut: what a dynamic pixel evaluates at most (docs/vpl.md).
      bound = 1.0f;
      const bounce::VplLightCuts& cuts = renderer_.vpls().cuts();
      for (std::size_t cell = 0; renderer_.hasVpls() && cell < cuts.cellEntries.size(); ++cell)
        bound = std::max(bound, static_cast<float>(cuts.lightsEvaluated(cell)));
    }
    return bounce::TonemapPass::CostDisplay{
        count, options_.shared.costMax.value_or(bounce::costScaleMax(bound))};
  }

  bool comparing() const {
    return referenceView_ != bounce::ReferenceView::Off && compare_.hasReference();
  }
  // What the window shows and the captures hold: the frame, or the frame beside the reference
  // (both radiance, tone-mapped alike).
  const bounce::gl::RenderTarget& shown() const { return comparing() ? *compared_ : *target_; }

  // A reference EXR (bounce-trace's, of the same camera and size) to compare the frame with;
  // the split view unless another comparison is on.
  void loadReference(const std::string& file) override {
    const bounce::Image reference = bounce::readExr(file);
    compare_.setReference(reference);
    referenceFile_ = file;
    if (referenceView_ == bounce::ReferenceView::Off) referenceView_ = bounce::ReferenceView::Split;
    const glm::ivec2 size = window_.framebufferSize();
    std::fprintf(stderr, "bounce-view: reference %s, %dx%d (%s)\n", file.c_str(), reference.width,
                 reference.height, std::string(bounce::referenceViewName(referenceView_)).c_str());
    if (reference.width != size.x || reference.height != size.y)
      std::fprintf(stderr,
                   "bounce-view: warning: the reference is %dx%d, the frame %dx%d: it is "
                   "stretched (open the viewer with --width %d --height %d to compare pixels)\n",
                   reference.width, reference.height, size.x, size.y, reference.width,
                   reference.height);
  }

  void setReferenceView(bounce::ReferenceView view) {
    if (view != bounce::ReferenceView::Off && !compare_.hasReference())
      throw std::runtime_error(
          "no reference to compare with (--reference FILE, the panel, or "
          "the script's reference FILE)");
    referenceView_ = view;
  }

  void saveScreenshot() {
    saveRequested_ = false;
    const bounce::Image radiance = shown().read();
    const std::string stem = "bounce-view-" + std::to_string(++screenshots_);
    try {
      save(radiance, stem + ".png", exposure_);
      save(radiance, stem + ".exr", exposure_);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "bounce-view: error: %s\n", e.what());  // keep viewing
    }
  }

  ViewerOptions options_;
  bounce::Scene scene_;
  std::optional<bounce::Bake> bake_;  // before renderer_, which reads it on construction
  std::filesystem::path bakeDir_;
  std::vector<std::string> bakeNotes_;
  std::vector<uint32_t> reportedLights_;  // the area-light cube choice last logged
  std::size_t reportedUnshadowed_ = static_cast<std::size_t>(-1);
  std::vector<bool> reportedMaps_;  // which punctual lights had a map when last logged
  bounce::gl::Window window_;
  bounce::ForwardRenderer renderer_;
  bounce::TonemapPass tonemap_;
  bounce::ReferenceComparePass compare_;
  bounce::DynamicSelection selection_;
  float objectSpeed_ = 1.0f;  // m/s
  std::unique_ptr<bounce::gl::RenderTarget> target_;
  std::unique_ptr<bounce::gl::RenderTarget> compared_;  // the frame beside the reference
  bounce::ReferenceView referenceView_ = bounce::ReferenceView::Off;
  std::string referenceFile_;
  std::vector<bounce::Camera> cameras_;
  std::size_t cameraIndex_ = 0;
  std::optional<bounce::FlyCamera> fly_;
  bounce::ViewerControls controls_;
  float speed_ = 1.0f;
  float exposure_ = 0.0f;
  bool saveRequested_ = false;
  int screenshots_ = 0;
  bounce::RenderMode modeBeforeCharts_ = bounce::RenderMode::Full;
  std::optional<bounce::gl::PanelLayer> panel_;  // none when ImGui cannot start
  bool panelShown_ = false;
  bounce::FrameTimes times_;
  std::vector<bounce::TimeSummary> passTimes_, cpuTimes_;  // the last 60 frames, per pass
  std::vector<std::string> bakeLines_;
  bool bakeStale_ = false;       // the bake (or the one on disk) does not match scene_
  bool lightsEdited_ = false;    // scene_ differs from the file: a re-bake is not written
  bounce::ViewerRebake rebake_;  // before the script state, after bake_
  std::array<std::optional<bounce::FlyCamera>, bounce::kScriptBookmarks> bookmarks_;
  bounce::ScriptReplay script_;
};

// --bake DIR, else the scene's bake found as bounce-render finds it, unless --no-bake.
LoadedBake findViewerBake(const ViewerOptions& options, const bounce::Scene& scene) {
  LoadedBake loaded;
  if (!options.shared.bake.empty()) {
    loaded.bake = bounce::readBake(options.shared.bake, scene);
    loaded.dir = options.shared.bake;
  } else if (!options.shared.noBake) {
    bounce::BakeSearch found =
        bounce::findSceneBake(options.shared.scene, scene, bounce::toolDirectory());
    for (const std::string& note : found.notes)
      std::fprintf(stderr, "bounce-view: %s\n", note.c_str());
    loaded.bake = std::move(found.bake);
    loaded.dir = found.dir;
    loaded.notes = found.notes;
    loaded.stale = found.stale();
  }
  return loaded;
}

}  // namespace

int runViewer(const ViewerOptions& options, Scene scene) {
  LoadedBake loaded = findViewerBake(options, scene);
  const RenderMode mode = options.shared.mode.empty()
                              ? (loaded.bake ? RenderMode::Full : RenderMode::Direct)
                              : *parseRenderMode(options.shared.mode);
  if (renderModeNeedsBake(mode) && !loaded.bake)
    throw std::runtime_error("--mode " + options.shared.mode +
                             " draws baked light: give --bake DIR" +
                             (options.shared.noBake ? " (and no --no-bake)" : ""));
  Viewer viewer(options, std::move(scene), std::move(loaded), mode);
  return viewer.run();
}

}  // namespace bounce
