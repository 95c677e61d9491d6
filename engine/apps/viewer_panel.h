// bounce-view's panel (Dear ImGui widgets, drawn by gl::PanelLayer): what is loaded and how good
// it is (the bake's facts, or why none is used), the view mode, exposure, cameras and camera
// bookmarks, the VPLs' light paths and clamp, a reference EXR to compare with, dynamic objects,
// the lights, and CPU and GPU frame times. It only reads a ViewerPanelView and returns
// what the user asked for this frame; the viewer applies it, as it does the keys.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "render/frame_profile.h"
#include "render/reference_view.h"
#include "render/render_mode.h"
#include "scene/scene.h"

namespace bounce {

// The last frames' times, ms, oldest first.
struct FrameTimes {
  static constexpr std::size_t kFrames = 240;
  std::vector<float> cpu, gpu;
  void add(double cpuMs, std::optional<double> gpuMs);
};

// The bake's VPLs as drawn (ForwardRenderer::VplSelection), for the panel's VPL controls.
struct PanelVpls {
  uint64_t paths = 0, totalPaths = 0;  // light paths drawn, of the bake's
  std::size_t vplCount = 0;            // VPLs drawn
  float clampDistance = 0.0f;          // r drawn, m
  float bakeClampDistance = 0.0f;      // the bake's r, m
};

struct ViewerPanelView {
  std::string scene;
  std::vector<std::string> bakeLines;  // bake_folder/bake_facts.h; empty without a bake
  std::vector<std::string> bakeNotes;  // which bake was found, or why one was passed over
  bool rebaking = false;               // a background re-bake is running
  std::string rebakeStatus;            // its progress, or how it ended
  double rebakeFraction = 0.0;
  std::vector<RenderMode> modes;  // the ones this bake allows
  RenderMode mode = RenderMode::Direct;
  float exposure = 0.0f;  // EV
  int msaa = 1;           // samples per pixel
  std::vector<std::string> cameras;
  std::size_t camera = 0;
  std::vector<bool> bookmarks;    // per slot (F1..): whether it holds a camera
  std::optional<PanelVpls> vpls;  // none without a bake with VPLs
  std::string referenceFile;      // the reference EXR loaded; empty: none
  ReferenceView referenceView = ReferenceView::Off;
  std::string object;                          // the dynamic object the keys move; empty: none
  std::size_t objectCount = 0;                 // dynamic objects (by name)
  const std::vector<Light>* lights = nullptr;  // the scene's punctual lights, as drawn now
  bool bakeStale = false;  // the bake no longer matches the scene (file or a light edit)
  const FrameTimes* times = nullptr;
  std::string costLegend;  // the cost view's scale (render/cost_view.h); empty in other modes
  // Per pass, GPU ms (gl/gpu_pass_timers.h), and the CPU spans of the frame (mean, p95 over the
  // last 60 frames; ForwardRenderer::profile).
  const std::vector<TimeSummary>* passTimes = nullptr;
  const std::vector<TimeSummary>* cpuTimes = nullptr;
};

struct ViewerPanelRequests {
  std::optional<RenderMode> mode;
  std::optional<float> exposure;
  std::optional<std::size_t> camera;
  std::optional<std::size_t> saveBookmark, goToBookmark;   // slot, 0-based
  std::optional<std::pair<uint64_t, float>> vplSelection;  // (light paths, clamp distance m)
  std::optional<std::string> loadReference;                // a reference EXR to load
  std::optional<ReferenceView> referenceView;
  bool nextObject = false;
  bool screenshot = false;
  bool rebake = false;
  bool cancelRebake = false;
  std::vector<std::pair<std::size_t, Light>> lightEdits;  // (index into Scene::lights, light)
};

ViewerPanelRequests drawViewerPanel(const ViewerPanelView& view);

}  // namespace bounce
