#include "bake_folder/probe_file.h"

#include <cmath>
#include <string>

#include "bake_folder/bake_manifest.h"  // the ranges
#include "io/atomic_file.h"
#include "io/byte_stream.h"
#include "io/load_error.h"

namespace bounce {
namespace {

constexpr char kMagic[8] = {'B', 'N', 'C', 'P', 'R', 'B', 'S', '\0'};
constexpr std::size_t kHeaderBytes = 32;
constexpr std::size_t kGridBytes = 56;
constexpr std::size_t kProbeBytes = 48;
constexpr std::size_t kCornerBytes = 2 * kVisibilitySlots + 4 * kVisibilitySlots;

// Each coordinate finite and within ±limit (NaN fails the comparison).
bool within(glm::vec3 v, float limit) {
  return std::abs(v.x) <= limit && std::abs(v.y) <= limit && std::abs(v.z) <= limit;
}

glm::vec3 readVec3(ByteReader& in, const char* what) {
  glm::vec3 v;
  for (int c = 0; c < 3; ++c) v[c] = in.f32(what);
  return v;
}

void checkGrid(const std::filesystem::path& file, const ProbeGrid& g, std::size_t index,
               uint64_t expectedFirst, uint64_t probes, uint64_t expectedCorner, uint64_t corners,
               const ProbeGrid* previous) {
  const std::string which = "grid " + std::to_string(index) + ": ";
  if (previous && g.instance <= previous->instance)
    throw LoadError(file, which + "instance " + std::to_string(g.instance) +
                              " does not follow the previous grid's " +
                              std::to_string(previous->instance) + " (ascending, one grid each)");
  for (int a = 0; a < 3; ++a)
    if (g.counts[a] < 2 || g.counts[a] > kMaxProbeGridCount)
      throw LoadError(file, which + "counts " + std::to_string(g.counts.x) + "x" +
                                std::to_string(g.counts.y) + "x" + std::to_string(g.counts.z) +
                                ": each must be in [2, " + std::to_string(kMaxProbeGridCount) +
                                "]");
  if (g.first != expectedFirst)
    throw LoadError(file, which + "first probe " + std::to_string(g.first) +
                              ", the grids before it hold " + std::to_string(expectedFirst));
  if (expectedFirst + g.probeCount() > probes)
    throw LoadError(file, which + "its probes run past the " + std::to_string(probes) +
                              " the header announces");
  if (!within(g.origin, kMaxBakeLength))
    throw LoadError(file,
                    which + "origin is not finite or beyond " + shortNumber(kMaxBakeLength) + " m");
  for (int a = 0; a < 3; ++a)
    if (!(g.spacing[a] > 0.0f && g.spacing[a] <= kMaxBakeLength))
      throw LoadError(file, which + "spacing is not in (0, " + shortNumber(kMaxBakeLength) +
                                "] m on every axis");
  if (!(g.normalOffset >= 0.0f && g.normalOffset <= kMaxBakeLength))
    throw LoadError(file,
                    which + "normal offset is not in [0, " + shortNumber(kMaxBakeLength) + "] m");
  if (g.firstCorner != expectedCorner)
    throw LoadError(file, which + "first corner " + std::to_string(g.firstCorner) +
                              ", the grids before it hold " + std::to_string(expectedCorner));
  if (g.cornerCount % 3 != 0)
    throw LoadError(file, which + std::to_string(g.cornerCount) + " corners: not 3 per triangle");
  if (expectedCorner + g.cornerCount > corners)
    throw LoadError(file, which + "its corners run past the " + std::to_string(corners) +
                              " the header announces");
}

// As a texel of visibility.bin (visibility_file.h).
void checkCorner(const std::filesystem::path& file, const TexelVisibility& c, std::size_t index,
                 uint64_t lights) {
  const std::string which = "corner " + std::to_string(index) + ": ";
  for (int s = 0; s < kVisibilitySlots; ++s) {
    const uint16_t l = c.light[s];
    if (l != kNoLight && l != kOtherLights && l >= lights)
      throw LoadError(file, which + "light " + std::to_string(l) + " of " + std::to_string(lights));
    if (!(c.visible[s] >= 0.0f && c.visible[s] <= 1.0f))
      throw LoadError(file, which + "visible fraction is not in [0, 1]");
    for (int r = 0; r < s; ++r)
      if (l != kNoLight && c.light[r] == l)
        throw LoadError(file, which + "names light " + std::to_string(l) + " twice");
  }
}

void checkProbe(const std::filesystem::path& file, const ProbeIrradiance& p, std::size_t index) {
  const std::string which = "probe " + std::to_string(index) + ": ";
  for (const glm::vec3& c : p.sh)
    if (!within(c, kMaxBakeIrradiance))
      throw LoadError(file, which + "a coefficient is not finite or beyond " +
                                shortNumber(kMaxBakeIrradiance) + " W/m^2");
  for (int c = 0; c < 3; ++c)
    if (!(kShY00 * p.sh[0][c] >= 0.0f))
      throw LoadError(file, which + "mean irradiance Y00*E00 is negative");
}

}  // namespace

std::vector<unsigned char> encodeProbes(const IrradianceProbes& probes) {
  ByteWriter out;
  out.raw(kMagic, sizeof kMagic);
  out.u32(kProbeFormatVersion);
  out.u32(static_cast<uint32_t>(probes.grids.size()));
  out.u32(static_cast<uint32_t>(probes.probes.size()));
  out.u32(static_cast<uint32_t>(probes.visibility.corners.size()));
  out.u32(probes.visibility.lightCount);
  out.u32(probes.visibility.punctualCount);
  for (const ProbeGrid& g : probes.grids) {
    out.u32(g.instance);
    out.u32(g.first);
    for (int a = 0; a < 3; ++a) out.u32(g.counts[a]);
    for (int a = 0; a < 3; ++a) out.f32(g.origin[a]);
    for (int a = 0; a < 3; ++a) out.f32(g.spacing[a]);
    out.f32(g.normalOffset);
    out.u32(g.firstCorner);
    out.u32(g.cornerCount);
  }
  for (const ProbeIrradiance& p : probes.probes)
    for (const glm::vec3& c : p.sh)
      for (int k = 0; k < 3; ++k) out.f32(c[k]);
  for (const TexelVisibility& c : probes.visibility.corners) {
    for (const uint16_t l : c.light) out.u16(l);
    for (const float v : c.visible) out.f32(v);
  }
  return out.take();
}

IrradianceProbes decodeProbes(const std::filesystem::path& file,
                              std::span<const unsigned char> bytes) {
  ByteReader in(file, bytes);
  in.need(kHeaderBytes, "the header");
  if (!in.matches(kMagic, sizeof kMagic))
    throw LoadError(file, "bad magic: not a bounce probe file");
  const uint32_t version = in.u32("the version");
  if (version != kProbeFormatVersion)
    throw LoadError(file, "format version " + std::to_string(version) +
                              ", this build reads version " + std::to_string(kProbeFormatVersion) +
                              ": rebake");
  const uint64_t grids = in.u32("the grid count");
  const uint64_t count = in.u32("the probe count");
  const uint64_t corners = in.u32("the corner count");
  IrradianceProbes probes;
  probes.visibility.lightCount = in.u32("the light count");
  probes.visibility.punctualCount = in.u32("the punctual light count");
  const uint64_t lights = uint64_t{probes.visibility.lightCount} + probes.visibility.punctualCount;
  if (lights > kOtherLights - 1u)
    throw LoadError(file, std::to_string(probes.visibility.lightCount) + " area and " +
                              std::to_string(probes.visibility.punctualCount) +
                              " punctual lights: at most 65533 in all can be named");
  const uint64_t expected =
      kHeaderBytes + kGridBytes * grids + kProbeBytes * count + kCornerBytes * corners;
  if (bytes.size() != expected)
    throw LoadError(file, std::to_string(grids) + " grids, " + std::to_string(count) +
                              " probes and " + std::to_string(corners) +
                              " corners announced need " + std::to_string(expected) +
                              " bytes, the file has " + std::to_string(bytes.size()));
  probes.grids.resize(grids);
  uint64_t next = 0, nextCorner = 0;
  for (std::size_t i = 0; i < grids; ++i) {
    ProbeGrid& g = probes.grids[i];
    g.instance = in.u32("a grid");
    g.first = in.u32("a grid");
    for (int a = 0; a < 3; ++a) g.counts[a] = in.u32("a grid");
    g.origin = readVec3(in, "a grid");
    g.spacing = readVec3(in, "a grid");
    g.normalOffset = in.f32("a grid");
    g.firstCorner = in.u32("a grid");
    g.cornerCount = in.u32("a grid");
    checkGrid(file, g, i, next, count, nextCorner, corners, i > 0 ? &probes.grids[i - 1] : nullptr);
    next += g.probeCount();
    nextCorner += g.cornerCount;
  }
  if (nextCorner != corners)
    throw LoadError(file, "the grids hold " + std::to_string(nextCorner) + " corners, the header " +
                              std::to_string(corners));
  if (next != count)
    throw LoadError(file, "the grids hold " + std::to_string(next) + " probes, the header " +
                              std::to_string(count));
  probes.probes.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    for (glm::vec3& c : probes.probes[i].sh) c = readVec3(in, "a probe");
    checkProbe(file, probes.probes[i], i);
  }
  probes.visibility.corners.resize(corners);
  for (std::size_t i = 0; i < corners; ++i) {
    TexelVisibility& c = probes.visibility.corners[i];
    for (uint16_t& l : c.light) l = in.u16("a corner");
    for (float& v : c.visible) v = in.f32("a corner");
    checkCorner(file, c, i, lights);
  }
  return probes;
}

void writeProbeFile(const std::filesystem::path& file, const IrradianceProbes& probes) {
  writeFileAtomically(file, encodeProbes(probes));
}

}  // namespace bounce
