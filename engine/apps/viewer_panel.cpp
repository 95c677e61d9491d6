#include "viewer_panel.h"

#include <algorithm>
#include <array>
#include <numeric>
#include <optional>

#include <glm/glm.hpp>

#include <imgui.h>

namespace bounce {
namespace {

void plot(const char* label, const std::vector<float>& ms) {
  if (ms.empty()) {
    ImGui::TextUnformatted((std::string(label) + ": not measured").c_str());
    return;
  }
  const float mean = std::accumulate(ms.begin(), ms.end(), 0.0f) / static_cast<float>(ms.size());
  const float top = *std::max_element(ms.begin(), ms.end());
  const std::string overlay = std::string(label) + " " + std::to_string(ms.back()).substr(0, 5) +
                              " ms (mean " + std::to_string(mean).substr(0, 5) + ")";
  ImGui::PlotLines("##times", ms.data(), static_cast<int>(ms.size()), 0, overlay.c_str(), 0.0f,
                   1.2f * top, ImVec2(0, 48));
}

// One light's fields: colour and power (intensity W/sr, or irradiance W/m² for a directional
// light, as colour × its largest channel), position (m) and direction. The edited light, if any.
std::optional<Light> editLight(std::size_t index, const Light& light) {
  ImGui::PushID(static_cast<int>(index));
  Light edited = light;
  bool changed = false;
  const bool directional = light.type == LightType::Directional;
  const char* kind = directional ? "directional" : light.type == LightType::Spot ? "spot" : "point";
  if (ImGui::TreeNode("light", "%s '%s'%s", kind, light.name.c_str(),
                      light.bakeDirect ? " (baked)" : "")) {
    glm::vec3& power = directional ? edited.irradiance : edited.intensity;
    float scale = std::max({power.r, power.g, power.b});
    glm::vec3 colour = scale > 0.0f ? power / scale : glm::vec3(1.0f);
    changed |= ImGui::ColorEdit3("colour", &colour.r, ImGuiColorEditFlags_Float);
    changed |= ImGui::DragFloat(directional ? "W/m^2" : "W/sr", &scale,
                                0.01f * std::max(scale, 1.0f), 0.0f, 1e6f, "%.4g");
    power = colour * std::max(scale, 0.0f);
    if (!directional) changed |= ImGui::DragFloat3("position (m)", &edited.position.x, 0.01f);
    if (light.type != LightType::Point) {
      changed |= ImGui::DragFloat3("direction", &edited.direction.x, 0.01f, -1.0f, 1.0f);
      edited.direction = glm::length(edited.direction) > 1e-6f ? glm::normalize(edited.direction)
                                                               : light.direction;
    }
    ImGui::TreePop();
  }
  ImGui::PopID();
  return changed ? std::optional<Light>(edited) : std::nullopt;
}

// What the bake is, whether it is stale, and the re-bake's button and progress.
void bakeSection(const ViewerPanelView& view, ViewerPanelRequests& requests) {
  if (ImGui::CollapsingHeader("Bake", ImGuiTreeNodeFlags_DefaultOpen)) {
    if (view.bakeLines.empty()) ImGui::TextUnformatted("no bake: direct light only");
    for (const std::string& line : view.bakeLines) ImGui::TextWrapped("%s", line.c_str());
    for (const std::string& note : view.bakeNotes) ImGui::TextWrapped("%s", note.c_str());
    const bool stale = view.bakeStale;
    if (stale)
      ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.2f, 1.0f),
                         "lighting needs to be rebuilt (stale bake)");
    if (view.rebaking) {
      ImGui::ProgressBar(static_cast<float>(view.rebakeFraction), ImVec2(-1, 0),
                         view.rebakeStatus.c_str());
      if (ImGui::Button("cancel")) requests.cancelRebake = true;
    } else {
      if (!view.rebakeStatus.empty()) ImGui::TextWrapped("re-bake: %s", view.rebakeStatus.c_str());
      if (ImGui::Button(view.bakeLines.empty() || stale ? "bake now" : "re-bake"))
        requests.rebake = true;
    }
  }
}

// The mode, the cost view's scale, the exposure, the samples per pixel and a screenshot.
void viewSection(const ViewerPanelView& view, ViewerPanelRequests& requests) {
  if (ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen)) {
    const std::string current(renderModeName(view.mode));
    if (ImGui::BeginCombo("mode (M)", current.c_str())) {
      for (const RenderMode mode : view.modes) {
        const std::string name(renderModeName(mode));
        if (ImGui::Selectable(name.c_str(), mode == view.mode)) requests.mode = mode;
      }
      ImGui::EndCombo();
    }
    if (!view.costLegend.empty()) ImGui::TextWrapped("%s", view.costLegend.c_str());
    float exposure = view.exposure;
    if (ImGui::SliderFloat("exposure (EV)", &exposure, -10.0f, 10.0f, "%+.1f"))
      requests.exposure = exposure;
    ImGui::Text("%d samples per pixel (--msaa)", view.msaa);
    if (ImGui::Button("screenshot (F12)")) requests.screenshot = true;
  }
}

// The scene's cameras and the camera bookmarks (F1..F4).
void cameraSections(const ViewerPanelView& view, ViewerPanelRequests& requests) {
  if (ImGui::CollapsingHeader("Cameras", ImGuiTreeNodeFlags_DefaultOpen)) {
    for (std::size_t i = 0; i < view.cameras.size(); ++i)
      if (ImGui::Selectable(view.cameras[i].c_str(), i == view.camera)) requests.camera = i;
  }

  if (ImGui::CollapsingHeader("Camera bookmarks")) {
    for (std::size_t i = 0; i < view.bookmarks.size(); ++i) {
      ImGui::PushID(static_cast<int>(i));
      const std::string slot = std::to_string(i + 1);
      std::string go = "go F", save = "save (Shift+F";
      go += slot;
      save += slot;
      save += ")";
      ImGui::BeginDisabled(!view.bookmarks[i]);
      if (ImGui::Button(go.c_str())) requests.goToBookmark = i;
      ImGui::EndDisabled();
      ImGui::SameLine();
      if (ImGui::Button(save.c_str())) requests.saveBookmark = i;
      ImGui::PopID();
    }
  }
}

// The bake's VPLs as drawn: the first N light paths and the clamp distance.
void vplSection(const ViewerPanelView& view, ViewerPanelRequests& requests) {
  if (view.vpls && ImGui::CollapsingHeader("VPLs")) {
    const PanelVpls& v = *view.vpls;
    int paths = static_cast<int>(v.paths);
    float clamp = v.clampDistance;
    // The first N light paths, their flux x total/N: the same estimate from fewer VPLs.
    bool changed = ImGui::SliderInt("light paths", &paths, 1, static_cast<int>(v.totalPaths), "%d",
                                    ImGuiSliderFlags_Logarithmic);
    ImGui::Text(
        "%zu VPLs of %llu paths (flux x %.3g)", v.vplCount,
        static_cast<unsigned long long>(v.totalPaths),
        static_cast<double>(v.totalPaths) / static_cast<double>(std::max<uint64_t>(v.paths, 1)));
    const float top = std::max(4.0f * v.bakeClampDistance, 0.1f);
    changed |= ImGui::SliderFloat("clamp r (m)", &clamp, 0.0f, top, "%.4f");
    if (ImGui::Button("the bake's")) {
      paths = static_cast<int>(v.totalPaths);
      clamp = v.bakeClampDistance;
      changed = true;
    }
    ImGui::SameLine();
    ImGui::Text("r = %.4f m", static_cast<double>(v.bakeClampDistance));
    if (changed) requests.vplSelection = {static_cast<uint64_t>(std::max(paths, 1)), clamp};
  }
}

// A reference EXR to load and how the frame is shown beside it.
void referenceSection(const ViewerPanelView& view, ViewerPanelRequests& requests) {
  if (ImGui::CollapsingHeader("Reference")) {
    // The path being typed lives across frames (the panel itself keeps no other state).
    static std::array<char, 1024> path{};
    ImGui::InputText("EXR", path.data(), path.size());
    if (ImGui::Button("load") && path[0] != '\0') requests.loadReference = std::string(path.data());
    if (!view.referenceFile.empty()) {
      ImGui::TextWrapped("%s", view.referenceFile.c_str());
      for (const ReferenceView v :
           {ReferenceView::Off, ReferenceView::Split, ReferenceView::Difference}) {
        if (v != ReferenceView::Off) ImGui::SameLine();
        const std::string name(referenceViewName(v));
        if (ImGui::RadioButton(name.c_str(), view.referenceView == v)) requests.referenceView = v;
      }
      ImGui::TextWrapped(
          "split: left the frame, right the reference; difference: red brighter, "
          "blue darker than the reference (full at 50%%)");
    }
  }
}

// The dynamic object the keys move, and the punctual lights' fields.
void sceneSections(const ViewerPanelView& view, ViewerPanelRequests& requests) {
  if (view.objectCount > 0 && ImGui::CollapsingHeader("Dynamic objects")) {
    ImGui::TextWrapped(
        "%s", view.object.empty() ? "none selected" : ("moving '" + view.object + "'").c_str());
    if (ImGui::Button("next (G)")) requests.nextObject = true;
    ImGui::TextWrapped("J/L, I/K, U/O move it (Shift x4)");
  }

  if (view.lights && !view.lights->empty() && ImGui::CollapsingHeader("Lights")) {
    for (std::size_t i = 0; i < view.lights->size(); ++i)
      if (std::optional<Light> edited = editLight(i, (*view.lights)[i]))
        requests.lightEdits.emplace_back(i, *edited);
  }
}

// CPU and GPU frame times and the last 60 frames per pass.
void frameTimeSection(const ViewerPanelView& view) {
  if (view.times && ImGui::CollapsingHeader("Frame time", ImGuiTreeNodeFlags_DefaultOpen)) {
    plot("CPU", view.times->cpu);
    plot("GPU", view.times->gpu);
    const auto table = [](const char* title, const std::vector<TimeSummary>* rows) {
      if (!rows || rows->empty()) return;
      ImGui::TextUnformatted(title);
      for (const TimeSummary& row : *rows)
        ImGui::Text("  %-28s %7.2f %7.2f", row.name.c_str(), row.mean, row.p95);
    };
    table("GPU per pass, ms (mean, p95; last 60 frames)", view.passTimes);
    table("CPU, ms (frame: build + submit, no wait)", view.cpuTimes);
  }
}

}  // namespace

void FrameTimes::add(double cpuMs, std::optional<double> gpuMs) {
  const auto push = [](std::vector<float>& v, double x) {
    if (v.size() == kFrames) v.erase(v.begin());
    v.push_back(static_cast<float>(x));
  };
  push(cpu, cpuMs);
  if (gpuMs) push(gpu, *gpuMs);
}

ViewerPanelRequests drawViewerPanel(const ViewerPanelView& view) {
  ViewerPanelRequests requests;
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(360, 0), ImGuiCond_FirstUseEver);
  ImGui::Begin("bounce-view (H hides)");

  bakeSection(view, requests);
  viewSection(view, requests);
  cameraSections(view, requests);
  vplSection(view, requests);
  referenceSection(view, requests);
  sceneSections(view, requests);
  frameTimeSection(view);
  ImGui::End();
  return requests;
}

}  // namespace bounce
