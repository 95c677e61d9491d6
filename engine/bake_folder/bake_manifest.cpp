#include "bake_folder/bake_manifest.h"

#include "io/byte_stream.h"

#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <limits>

#include <nlohmann/json.hpp>

#include "bake_folder/json_fields.h"
#include "io/json_depth.h"
#include "io/load_error.h"

namespace bounce {
namespace {

using Json = nlohmann::json;

Json rgb(const glm::dvec3& v) {
  return Json::array({v.r, v.g, v.b});
}

constexpr int64_t kIntMax = std::numeric_limits<int>::max();

BakeManifest::Vpls readVpls(const JsonFields& f) {
  BakeManifest::Vpls v;
  v.count = f.count("count");
  v.paths = f.count("paths");
  v.totalFlux = f.rgb(f.need("totalFlux", true, "array"), f.name("totalFlux"));
  const Json* perBounce = f.find("fluxPerBounce");
  for (const Json& flux : f.need("fluxPerBounce", perBounce && perBounce->is_array(), "array"))
    v.fluxPerBounce.push_back(f.rgb(flux, f.name("fluxPerBounce")));
  v.relativeError = f.real("relativeError");
  v.errorTarget = f.real("errorTarget");
  v.cap = f.integer("cap", 0, kIntMax);
  v.clampDistance = f.real("clampDistance", 0.0, kMaxBakeLength);
  return v;
}

BakeManifest::Visibility readVisibility(const JsonFields& f) {
  BakeManifest::Visibility v;
  v.lights = f.count("lights");
  v.punctualLights = f.count("punctualLights");
  v.slotsPerTexel = f.count("slotsPerTexel");
  v.samplesPerLight = f.count("samplesPerLight");
  v.texelsReached = f.count("texelsReached");
  v.texelsOverSlots = f.count("texelsOverSlots");
  v.otherLightsShare = f.real("otherLightsShare", 0.0, 1.0);
  v.rays = f.count("rays");
  return v;
}

BakeManifest::Probes readProbes(const JsonFields& f) {
  BakeManifest::Probes p;
  p.count = f.count("count");
  p.grids = f.count("grids");
  p.invalidFilled = f.count("invalidFilled");
  p.unread = f.count("unread");
  p.samplesTotal = f.count("samplesTotal");
  p.samplesPerProbeMin = f.count("samplesPerProbeMin");
  p.samplesPerProbeMax = f.count("samplesPerProbeMax");
  p.meanRelativeError = f.real("meanRelativeError");
  p.targetError = f.real("targetError");
  p.leakTestRays = f.count("leakTestRays");
  return p;
}

void readMeasured(const JsonFields& f, BakeManifest::Measured& m) {
  const JsonFields s = f.object("seconds");
  BakeManifest::Measured::Seconds& t = m.seconds;
  for (auto [key, value] : {std::pair{"load", &t.load},
                            {"atlas", &t.atlas},
                            {"rayKernel", &t.rayKernel},
                            {"coverage", &t.coverage},
                            {"leakGuard", &t.leakGuard},
                            {"irradiance", &t.irradiance},
                            {"visibility", &t.visibility},
                            {"denoise", &t.denoise},
                            {"dilate", &t.dilate},
                            {"stitch", &t.stitch},
                            {"vpls", &t.vpls},
                            {"total", &t.total}})
    *value = s.real(key);
  // Bakes before the probes have no probe stage.
  if (s.find("probes")) t.probes = s.real("probes");
  m.raysPerSecond = f.real("raysPerSecond");
  m.peakBytes = f.real("peakBytes");
  m.estimatedPeakBytes = f.real("estimatedPeakBytes");
}

}  // namespace

std::string shortNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

std::string fnv1a64Hex(std::span<const unsigned char> bytes) {
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016" PRIx64, fnv1a64(bytes));
  return hex;
}

std::string manifestText(const BakeManifest& m) {
  const BakeManifest::Atlas& a = m.atlas;
  const BakeManifest::Measured::Seconds& t = m.measured.seconds;
  Json files = Json::object();
  for (const auto& [name, record] : m.files)
    files[name] = {{"bytes", record.bytes}, {"hash", record.hash}};
  Json json = {
      {"formatVersion", m.formatVersion},
      {"sceneHash", m.sceneHash},
      {"sceneParts", m.sceneParts},
      {"settingsHash", m.settingsHash},
      {"scene", m.scene},
      {"settings", bakeSettingsJson(m.settings)},
      {"lightmap",
       {{"quantity", "irradiance"},
        {"unit", "W/m^2"},
        {"holds",
         "indirect light (two or more reflections counted at the viewer, i.e. light that "
         "reflected at least once before reaching the texel) of every light and emitter, plus "
         "the direct light of the baked-only lights listed in directBaked"},
        {"indirect", "all"},
        {"directBaked", m.directBaked}}},
      {"atlas",
       {{"width", a.width},
        {"height", a.height},
        {"texelSize", a.texelSize},
        {"texelRule", a.texelRule},
        {"staticArea", a.staticArea},
        {"weightedArea", a.weightedArea},
        {"padding", a.padding},
        {"charts", a.charts},
        {"regions", a.regions},
        {"vplLitInstances", a.vplLitInstances},
        {"utilisation", a.utilisation},
        {"coveredTexels", a.coveredTexels},
        {"invalidTexels", a.invalidTexels},
        {"notes", a.notes}}},
      {"samples",
       {{"total", m.samples.total},
        {"perTexelMean", m.samples.perTexelMean},
        {"perTexelMin", m.samples.perTexelMin},
        {"perTexelMax", m.samples.perTexelMax},
        {"nonFinite", m.samples.nonFinite}}},
      {"estimatedError",
       {{"what",
         "relative error of the delivered lightmap (luminance, after the denoiser, fill, "
         "dilation and seams), |delivered - converged| / converged, estimated per texel from "
         "two independent halves of its samples sent through the same filters, plus the "
         "denoiser's and the adaptive stop's estimated bias: mean and p95 over lit texels with "
         "samples of their own; luminanceWeighted = sum of the errors / sum of E; "
         "unknownTexels: lit texels filled from their neighbours, whose error is not known "
         "(1 in error.exr), left out of the three"},
        {"file", "error.exr"},
        {"mean", m.estimatedError.mean},
        {"p95", m.estimatedError.p95},
        {"luminanceWeighted", m.estimatedError.luminanceWeighted},
        {"unknownTexels", m.estimatedError.unknownTexels},
        {"target", m.estimatedError.target},
        {"beforeFilters",
         {{"what",
           "relative standard error of each texel's irradiance from its own sample variance, "
           "before any filter: what the adaptive stop compares with target"},
          {"mean", m.estimatedError.beforeFiltersMean},
          {"p95", m.estimatedError.beforeFiltersP95}}}}},
      {"leaks",
       {{"pointsInsideGeometry", m.leaks.pointsInsideGeometry},
        {"pointsAcrossWalls", m.leaks.pointsAcrossWalls},
        {"invalidTexelsFilled", m.leaks.invalidTexelsFilled}}},
      {"seams",
       {{"count", m.seams.count},
        {"relativeMismatchAfterStitching", m.seams.relativeMismatchAfterStitching}}},
      {"rays", {{"traced", m.rays.traced}, {"backend", m.rays.backend}}},
      {"measured",
       {{"what",
         "run-dependent: differs between bakes of identical inputs; everything else in "
         "bake.json does not"},
        {"seconds",
         {{"load", t.load},
          {"atlas", t.atlas},
          {"rayKernel", t.rayKernel},
          {"coverage", t.coverage},
          {"leakGuard", t.leakGuard},
          {"irradiance", t.irradiance},
          {"visibility", t.visibility},
          {"denoise", t.denoise},
          {"dilate", t.dilate},
          {"stitch", t.stitch},
          {"vpls", t.vpls},
          {"probes", t.probes},
          {"total", t.total}}},
        {"raysPerSecond", m.measured.raysPerSecond},
        {"peakBytes", m.measured.peakBytes},
        {"estimatedPeakBytes", m.measured.estimatedPeakBytes},
        {"memory",
         "resident set in bytes: the process's peak at the end of the bake, and the estimate "
         "made after the atlas (bake_memory.h, which depends on the thread count)"}}},
      {"files", files}};
  if (m.vpls) {
    const BakeManifest::Vpls& v = *m.vpls;
    Json perBounce = Json::array();
    for (const glm::dvec3& flux : v.fluxPerBounce) perBounce.push_back(rgb(flux));
    json["vpls"] = {
        {"file", "vpls"},
        {"count", v.count},
        {"paths", v.paths},
        {"unit", "W"},
        {"holds",
         "indirect light only: one VPL per diffuse hit of a light path from the first bounce "
         "on; flux already multiplied by the albedo of its surface; it adds "
         "Phi/pi cos(theta_vpl) cos(theta_x) / d^2 rho_x/pi (docs/vpl.md)"},
        {"totalFlux", rgb(v.totalFlux)},
        {"fluxPerBounce", perBounce},
        {"relativeError", v.relativeError},
        {"errorTarget", v.errorTarget},
        {"cap", v.cap},
        {"clampDistance", v.clampDistance}};
  }
  if (m.visibility) {
    const BakeManifest::Visibility& v = *m.visibility;
    json["visibility"] = {
        {"file", "visibility.bin"},
        {"what",
         "per texel, the visible fraction V of each static light's unshadowed irradiance "
         "(bake_folder/light_visibility.h): lights 0..lights-1 are the static area lights, then "
         "punctualLights the scene's point, spot and directional lights; the renderer multiplies "
         "its exact unshadowed irradiance by it"},
        {"lights", v.lights},
        {"punctualLights", v.punctualLights},
        {"slotsPerTexel", v.slotsPerTexel},
        {"samplesPerLight", v.samplesPerLight},
        {"texelsReached", v.texelsReached},
        {"texelsOverSlots", v.texelsOverSlots},
        {"otherLightsShare", v.otherLightsShare},
        {"rays", v.rays}};
  }
  if (m.probes) {
    const BakeManifest::Probes& p = *m.probes;
    json["probes"] = {
        {"file", "probes.bin"},
        {"unit", "W/m^2"},
        {"holds",
         "per static instance without a lightmap region, a grid of probes, each the L1 spherical "
         "harmonics of the irradiance E(n) it would give a surface of normal n, the light the "
         "lightmap holds (docs/probes.md)"},
        {"count", p.count},
        {"grids", p.grids},
        {"invalidFilled", p.invalidFilled},
        {"unread", p.unread},
        {"samplesTotal", p.samplesTotal},
        {"samplesPerProbeMin", p.samplesPerProbeMin},
        {"samplesPerProbeMax", p.samplesPerProbeMax},
        {"meanRelativeError", p.meanRelativeError},
        {"targetError", p.targetError},
        {"leakTestRays", p.leakTestRays}};
  }
  return json.dump(1) + "\n";
}

BakeManifest parseManifest(const std::filesystem::path& file, const std::string& text) {
  checkJsonDepth(file, text);  // before the recursive parser
  Json json;
  try {
    json = Json::parse(text);
  } catch (const Json::exception& e) {
    throw LoadError(file, std::string("not JSON: ") + e.what());
  }
  if (!json.is_object()) throw LoadError(file, "not a JSON object");
  const JsonFields root(file, json, "");
  BakeManifest m;
  // The version first: an older bake is named as such, not by a field it lacks.
  const Json* version = root.find("formatVersion");
  if (version == nullptr || !version->is_number_integer())
    root.fail("no integer \"formatVersion\"");
  if (version->is_number_unsigned() ? version->get<uint64_t>() != kBakeFormatVersion
                                    : version->get<int64_t>() != kBakeFormatVersion)
    root.fail("format version " + version->dump() + ", this build reads version " +
              std::to_string(kBakeFormatVersion) + ": rebake");
  m.formatVersion = kBakeFormatVersion;
  m.sceneHash = root.text("sceneHash");
  m.scene = root.text("scene");
  const JsonFields parts = root.object("sceneParts");
  for (auto it = parts.json().begin(); it != parts.json().end(); ++it)
    m.sceneParts[it.key()] = parts.text(it.key().c_str());
  m.settingsHash = root.text("settingsHash");

  m.settings = parseBakeSettings(file, root.object("settings").json(), "settings");
  m.directBaked = root.object("lightmap").texts("directBaked");

  const JsonFields a = root.object("atlas");
  m.atlas.width = static_cast<int>(a.integer("width", 1, 65536));
  m.atlas.height = static_cast<int>(a.integer("height", 1, 65536));
  m.atlas.texelSize = a.real("texelSize", 0.0, kMaxBakeLength);
  m.atlas.texelRule = a.text("texelRule");
  m.atlas.staticArea = a.real("staticArea");
  m.atlas.weightedArea = a.real("weightedArea");
  m.atlas.padding = static_cast<int>(a.integer("padding", 0, kIntMax));
  m.atlas.charts = static_cast<int>(a.integer("charts", 0, kIntMax));
  m.atlas.regions = a.count("regions");
  m.atlas.vplLitInstances = a.count("vplLitInstances");
  m.atlas.utilisation = a.real("utilisation", 0.0, 1.0);
  m.atlas.coveredTexels = a.count("coveredTexels");
  m.atlas.invalidTexels = a.count("invalidTexels");
  m.atlas.notes = a.texts("notes");

  const JsonFields samples = root.object("samples");
  m.samples.total = samples.count("total");
  m.samples.perTexelMean = samples.real("perTexelMean");
  m.samples.perTexelMin = samples.count("perTexelMin");
  m.samples.perTexelMax = samples.count("perTexelMax");
  m.samples.nonFinite = samples.count("nonFinite");
  const JsonFields error = root.object("estimatedError");
  m.estimatedError.mean = error.real("mean");
  m.estimatedError.p95 = error.real("p95");
  m.estimatedError.target = error.real("target");
  // Bakes before the delivered error have only the per-texel figure, as mean and p95.
  if (error.find("luminanceWeighted"))
    m.estimatedError.luminanceWeighted = error.real("luminanceWeighted");
  if (error.find("unknownTexels")) m.estimatedError.unknownTexels = error.count("unknownTexels");
  if (error.find("beforeFilters")) {
    const JsonFields before = error.object("beforeFilters");
    m.estimatedError.beforeFiltersMean = before.real("mean");
    m.estimatedError.beforeFiltersP95 = before.real("p95");
  }
  const JsonFields leaks = root.object("leaks");
  m.leaks.pointsInsideGeometry = leaks.count("pointsInsideGeometry");
  m.leaks.pointsAcrossWalls = leaks.count("pointsAcrossWalls");
  m.leaks.invalidTexelsFilled = leaks.count("invalidTexelsFilled");
  const JsonFields seams = root.object("seams");
  m.seams.count = seams.count("count");
  m.seams.relativeMismatchAfterStitching = seams.real("relativeMismatchAfterStitching");
  const JsonFields rays = root.object("rays");
  m.rays.traced = rays.count("traced");
  m.rays.backend = rays.text("backend");
  readMeasured(root.object("measured"), m.measured);
  if (root.find("vpls")) m.vpls = readVpls(root.object("vpls"));
  if (root.find("visibility")) m.visibility = readVisibility(root.object("visibility"));
  if (root.find("probes")) m.probes = readProbes(root.object("probes"));

  if (root.find("files") == nullptr)
    root.fail("no \"files\" (the sizes and hashes of the folder's files): rebake");
  const JsonFields files = root.object("files");
  if (files.json().empty()) root.fail("\"files\" is empty: rebake");
  for (auto it = files.json().begin(); it != files.json().end(); ++it) {
    const JsonFields record = files.object(it.key().c_str());
    BakeFileRecord& r = m.files[it.key()];
    r.bytes = record.count("bytes");
    r.hash = record.text("hash");
  }
  return m;
}

}  // namespace bounce
