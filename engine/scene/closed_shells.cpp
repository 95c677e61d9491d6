#include "scene/closed_shells.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <unordered_map>
#include <vector>

#include <tbb/parallel_for.h>

#include "scene/surface_rules.h"

namespace bounce {

namespace {

constexpr double kPi = 3.14159265358979323846;

// A light source as seen from the shells: a point, or a direction at infinity.
struct Source {
  glm::dvec3 position{0.0};
  bool atInfinity = false;
};

uint32_t floatBits(float f) {
  if (f == 0.0f) f = 0.0f;  // −0 and +0 are one position
  uint32_t bits = 0;
  std::memcpy(&bits, &f, sizeof bits);
  return bits;
}

struct PositionKey {
  std::array<uint32_t, 3> bits;
  bool operator==(const PositionKey&) const = default;
};
struct PositionHash {
  std::size_t operator()(const PositionKey& k) const {
    uint64_t h = 1469598103934665603ull;
    for (const uint32_t b : k.bits) h = (h ^ b) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

// One closed component of a mesh, its triangles wound one consistent way: `reversed[k]` says
// whether triangles[k] runs against the file's winding in that orientation.
struct Shell {
  std::vector<uint32_t> triangles;
  std::vector<uint8_t> reversed;
  glm::vec3 lo{0.0f}, hi{0.0f};  // bounding box, object space
  double volume = 0.0;           // signed, in the consistent orientation: > 0 when it faces out

  glm::uvec3 corners(const Mesh& mesh, std::size_t k) const {
    const uint32_t* i = &mesh.indices[3 * triangles[k]];
    return reversed[k] ? glm::uvec3(i[0], i[2], i[1]) : glm::uvec3(i[0], i[1], i[2]);
  }
};

// The mesh's shells: triangles joined across edges of equal end positions; a component is a
// shell when each of its edges has exactly two triangles and the triangles can be wound
// consistently (an orientable closed surface). The file's winding may differ from triangle to
// triangle (some exporters wind part of a solid inwards); the consistent orientation is found
// by walking across edges. Triangles with two equal corner positions join nothing.
std::vector<Shell> closedShells(const Mesh& mesh) {
  const std::size_t triangles = mesh.triangleCount();
  std::unordered_map<PositionKey, uint32_t, PositionHash> weld;
  weld.reserve(mesh.positions.size());
  std::vector<uint32_t> welded(mesh.positions.size());
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const glm::vec3 p = mesh.positions[v];
    const PositionKey key{{floatBits(p.x), floatBits(p.y), floatBits(p.z)}};
    welded[v] = weld.try_emplace(key, static_cast<uint32_t>(weld.size())).first->second;
  }
  // Per undirected edge: the triangles along it and the direction each runs it in.
  struct EdgeUse {
    uint32_t count = 0;
    uint32_t triangle[2] = {0, 0};
    bool ascending[2] = {false, false};  // runs from the lower to the higher welded index
  };
  std::unordered_map<uint64_t, EdgeUse> edges;
  edges.reserve(triangles * 3 / 2 + 1);
  auto edgeKey = [&](std::size_t t, int e) {
    const uint32_t a = welded[mesh.indices[3 * t + e]];
    const uint32_t b = welded[mesh.indices[3 * t + (e + 1) % 3]];
    return std::pair<uint64_t, bool>((static_cast<uint64_t>(std::min(a, b)) << 32) | std::max(a, b),
                                     a < b);
  };
  std::vector<uint8_t> usable(triangles, 1);
  for (std::size_t t = 0; t < triangles; ++t) {
    const uint32_t c[3] = {welded[mesh.indices[3 * t]], welded[mesh.indices[3 * t + 1]],
                           welded[mesh.indices[3 * t + 2]]};
    if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2]) {
      usable[t] = 0;
      continue;
    }
    for (int e = 0; e < 3; ++e) {
      const auto [key, ascending] = edgeKey(t, e);
      EdgeUse& use = edges[key];
      if (use.count < 2) {
        use.triangle[use.count] = static_cast<uint32_t>(t);
        use.ascending[use.count] = ascending;
      }
      ++use.count;
    }
  }
  // Walk each component, winding every triangle like the one it was reached from (two
  // consistently wound triangles run their shared edge in opposite directions).
  std::vector<int8_t> reversed(triangles, -1);  // -1: not reached yet
  std::vector<Shell> shells;
  std::vector<uint32_t> stack;
  for (std::size_t seed = 0; seed < triangles; ++seed) {
    if (!usable[seed] || reversed[seed] >= 0) continue;
    Shell shell;
    bool closed = true;
    reversed[seed] = 0;
    stack.assign(1, static_cast<uint32_t>(seed));
    while (!stack.empty()) {
      const uint32_t t = stack.back();
      stack.pop_back();
      shell.triangles.push_back(t);
      shell.reversed.push_back(static_cast<uint8_t>(reversed[t]));
      for (int e = 0; e < 3; ++e) {
        const EdgeUse& use = edges.at(edgeKey(t, e).first);
        if (use.count != 2 || use.triangle[0] == use.triangle[1]) {
          closed = false;
          continue;
        }
        const int self = use.triangle[0] == t ? 0 : 1;
        const uint32_t other = use.triangle[1 - self];
        // Consistent when the two run the edge in opposite directions after their reversals.
        const bool runsSame = use.ascending[0] == use.ascending[1];
        const auto wanted = static_cast<int8_t>(reversed[t] ^ (runsSame ? 1 : 0));
        if (reversed[other] < 0) {
          reversed[other] = wanted;
          stack.push_back(other);
        } else if (reversed[other] != wanted) {
          closed = false;  // not orientable (a Möbius-like join): no inside to speak of
        }
      }
    }
    if (!closed) continue;
    shell.lo = shell.hi = mesh.positions[mesh.indices[3 * seed]];
    for (const uint32_t t : shell.triangles)
      for (int k = 0; k < 3; ++k) {
        shell.lo = glm::min(shell.lo, mesh.positions[mesh.indices[3 * t + k]]);
        shell.hi = glm::max(shell.hi, mesh.positions[mesh.indices[3 * t + k]]);
      }
    // Volume by the divergence theorem about the box's centre (fewer cancelling digits).
    const glm::dvec3 o = (glm::dvec3(shell.lo) + glm::dvec3(shell.hi)) * 0.5;
    for (std::size_t k = 0; k < shell.triangles.size(); ++k) {
      const glm::uvec3 c = shell.corners(mesh, k);
      const glm::dvec3 a = glm::dvec3(mesh.positions[c.x]) - o;
      const glm::dvec3 b = glm::dvec3(mesh.positions[c.y]) - o;
      const glm::dvec3 d = glm::dvec3(mesh.positions[c.z]) - o;
      shell.volume += glm::dot(a, glm::cross(b, d)) / 6.0;
    }
    shells.push_back(std::move(shell));
  }
  return shells;
}

// Generalized winding number of the shell about p: the solid angle its triangles subtend
// (Van Oosterom and Strackee's formula), over 4π. In the shell's consistent orientation: +1
// inside when it faces out, −1 inside when it faces in, 0 outside; ±½ on the surface.
double windingNumber(const Mesh& mesh, const Shell& shell, glm::dvec3 p) {
  double omega = 0.0;
  for (std::size_t k = 0; k < shell.triangles.size(); ++k) {
    const glm::uvec3 corner = shell.corners(mesh, k);
    const glm::dvec3 a = glm::dvec3(mesh.positions[corner.x]) - p;
    const glm::dvec3 b = glm::dvec3(mesh.positions[corner.y]) - p;
    const glm::dvec3 c = glm::dvec3(mesh.positions[corner.z]) - p;
    const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
    const double numerator = glm::dot(a, glm::cross(b, c));
    const double denominator =
        la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
    omega += 2.0 * std::atan2(numerator, denominator);
  }
  return omega / (4.0 * kPi);
}

std::vector<Source> lightSources(const Scene& scene) {
  std::vector<Source> sources;
  for (const Light& light : scene.lights) {
    if (light.type == LightType::Directional)
      sources.push_back({glm::dvec3(0.0), true});
    else
      sources.push_back({glm::dvec3(light.position), false});
  }
  for (const Instance& instance : scene.instances) {
    const Mesh& mesh = scene.meshes.at(instance.mesh);
    const Material& material = materialOf(scene, mesh.material);
    if (!material.isEmissive()) continue;
    const glm::dmat4 toWorld(instance.transform);
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
      const glm::dvec3 p0(toWorld * glm::dvec4(mesh.positions[mesh.indices[3 * t]], 1.0));
      const glm::dvec3 p1(toWorld * glm::dvec4(mesh.positions[mesh.indices[3 * t + 1]], 1.0));
      const glm::dvec3 p2(toWorld * glm::dvec4(mesh.positions[mesh.indices[3 * t + 2]], 1.0));
      glm::dvec3 n = glm::cross(p1 - p0, p2 - p0);
      if (glm::determinant(glm::dmat3(toWorld)) < 0.0) n = -n;  // flatten()'s mirror rule
      const double twiceArea = glm::length(n);
      if (!(twiceArea > 0.0) || !std::isfinite(twiceArea)) continue;
      // Just off the emitting side(s): a hundredth of the triangle's size.
      const glm::dvec3 off = n / twiceArea * (0.01 * std::sqrt(twiceArea));
      const glm::dvec3 centre = (p0 + p1 + p2) / 3.0;
      sources.push_back({centre + off, false});
      if (material.doubleSided) sources.push_back({centre - off, false});
    }
  }
  return sources;
}

// Reverses the winding of `flip`ped triangles and turns their shading normals to the new
// front; a vertex shared with a triangle that keeps its winding is copied first.
void turnTriangles(Mesh& mesh, const std::vector<uint8_t>& flip) {
  const std::size_t vertices = mesh.positions.size();
  std::vector<uint8_t> usedByFlipped(vertices, 0), usedByKept(vertices, 0);
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k) (flip[t] ? usedByFlipped : usedByKept)[mesh.indices[3 * t + k]] = 1;
  std::vector<uint32_t> copyOf(vertices);
  std::iota(copyOf.begin(), copyOf.end(), 0u);
  for (std::size_t v = 0; v < vertices; ++v) {
    if (!usedByFlipped[v] || !usedByKept[v]) continue;
    copyOf[v] = static_cast<uint32_t>(mesh.positions.size());
    mesh.positions.push_back(mesh.positions[v]);
    mesh.normals.push_back(mesh.normals[v]);
    if (!mesh.uv0.empty()) mesh.uv0.push_back(mesh.uv0[v]);
    if (!mesh.uv1.empty()) mesh.uv1.push_back(mesh.uv1[v]);
  }
  std::vector<glm::vec3> newFront(mesh.positions.size(), glm::vec3(0.0f));
  std::vector<uint8_t> turned(mesh.positions.size(), 0);
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    if (!flip[t]) continue;
    uint32_t* tri = &mesh.indices[3 * t];
    for (int k = 0; k < 3; ++k) tri[k] = copyOf[tri[k]];
    std::swap(tri[1], tri[2]);
    const glm::vec3 cross = glm::cross(mesh.positions[tri[1]] - mesh.positions[tri[0]],
                                       mesh.positions[tri[2]] - mesh.positions[tri[0]]);
    for (int k = 0; k < 3; ++k) newFront[tri[k]] += cross, turned[tri[k]] = 1;
  }
  // A normal that disagrees with the turned triangles around it was the old front's: turn it.
  for (std::size_t v = 0; v < mesh.positions.size(); ++v)
    if (turned[v] && glm::dot(mesh.normals[v], newFront[v]) < 0.0f)
      mesh.normals[v] = -mesh.normals[v];
}

// Which side of `shell` (of a mesh placed at the instances whose inverse transforms are
// `toObject`) the sources light.
struct LitSides {
  bool inside = false, outside = false;
};
LitSides litSides(const Mesh& mesh, const Shell& shell, const std::vector<glm::dmat4>& toObject,
                  const std::vector<Source>& sources) {
  LitSides lit;
  for (const glm::dmat4& objectOf : toObject)
    for (const Source& source : sources) {
      if (lit.inside && lit.outside) return lit;  // lit on both sides: decided
      if (source.atInfinity) {
        lit.outside = true;
        continue;
      }
      const glm::dvec3 p(objectOf * glm::dvec4(source.position, 1.0));
      if (glm::any(glm::lessThan(p, glm::dvec3(shell.lo))) ||
          glm::any(glm::greaterThan(p, glm::dvec3(shell.hi)))) {
        lit.outside = true;
        continue;
      }
      const double w = std::abs(windingNumber(mesh, shell, p));
      if (w > 0.25) lit.inside = true;
      if (w < 0.75) lit.outside = true;
    }
  return lit;
}

// Mesh m's shells turned to their lit side; each mesh on its own, its shells in parallel (each
// writes only its own triangles' flips).
ShellOrientation orientMeshShells(Scene& scene, uint32_t m, const std::vector<Source>& sources) {
  ShellOrientation result;
  Mesh& mesh = scene.meshes[m];
  if (materialOf(scene, mesh.material).isEmissive()) return result;  // its own light counts
  std::vector<glm::dmat4> toObject;
  for (const Instance& instance : scene.instances)
    if (instance.mesh == m) toObject.push_back(glm::inverse(glm::dmat4(instance.transform)));
  if (toObject.empty()) return result;
  const std::vector<Shell> shells = closedShells(mesh);
  result.closedShells = shells.size();
  std::vector<uint8_t> flip(mesh.triangleCount(), 0);
  std::vector<uint8_t> turned(shells.size(), 0);
  tbb::parallel_for(std::size_t{0}, shells.size(), [&](std::size_t s) {
    const Shell& shell = shells[s];
    // Flat (two sheets back to back, no inside): nothing to decide.
    const glm::dvec3 extent = glm::dvec3(shell.hi) - glm::dvec3(shell.lo);
    if (!(std::abs(shell.volume) > 1e-9 * std::pow(glm::dot(extent, extent), 1.5))) return;
    const LitSides lit = litSides(mesh, shell, toObject, sources);
    if (lit.inside == lit.outside) return;  // lit on both sides, or on neither: as written
    // Face the lit side: out when the sources are outside. The consistent orientation faces
    // out when its signed volume is positive; each triangle's file winding may differ from it.
    const bool reverseAll = lit.outside ? shell.volume < 0.0 : shell.volume > 0.0;
    for (std::size_t k = 0; k < shell.triangles.size(); ++k) {
      const bool reverse = (shell.reversed[k] != 0) != reverseAll;
      flip[shell.triangles[k]] = reverse ? 1 : 0;
      turned[s] = turned[s] || reverse;
    }
  });
  result.turned = static_cast<std::size_t>(std::count(turned.begin(), turned.end(), 1));
  if (result.turned > 0) turnTriangles(mesh, flip);
  return result;
}

}  // namespace

ShellOrientation orientClosedShells(Scene& scene) {
  ShellOrientation result;
  const std::vector<Source> sources = lightSources(scene);
  if (sources.empty()) return result;
  // Each mesh on its own (in parallel): it reads the scene and writes only itself.
  std::vector<ShellOrientation> perMesh(scene.meshes.size());
  tbb::parallel_for(std::size_t{0}, scene.meshes.size(), [&](std::size_t m) {
    perMesh[m] = orientMeshShells(scene, static_cast<uint32_t>(m), sources);
  });
  for (const ShellOrientation& mesh : perMesh) {
    result.closedShells += mesh.closedShells;
    result.turned += mesh.turned;
  }
  return result;
}

}  // namespace bounce
