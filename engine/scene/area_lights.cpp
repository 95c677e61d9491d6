#include "scene/area_lights.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <unordered_map>

#include "scene/surface_rules.h"

namespace bounce {

std::size_t AreaLightSet::staticCount() const {
  return static_cast<std::size_t>(
      std::count_if(lights.begin(), lights.end(),
                    [](const AreaLight& l) { return l.mobility == Mobility::Static; }));
}

std::vector<EmitterTriangle> emitterTriangles(const Scene& scene,
                                              std::span<const glm::mat4> transforms) {
  std::vector<EmitterTriangle> triangles;
  for (std::size_t i = 0; i < scene.instances.size(); ++i) {
    const Instance& instance = scene.instances[i];
    if (instance.mesh >= scene.meshes.size()) continue;
    const Mesh& mesh = scene.meshes[instance.mesh];
    const Material& material = materialOf(scene, mesh.material);
    const glm::vec3 radiance = emittedRadiance(material);
    if (radiance == glm::vec3(0.0f)) continue;
    const glm::mat4 model = i < transforms.size() ? transforms[i] : instance.transform;
    const bool mirrored = glm::determinant(glm::mat3(model)) < 0.0f;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      glm::vec3 p[3];
      for (int c = 0; c < 3; ++c) {
        const uint32_t v = mesh.indices[t + static_cast<std::size_t>(c)];
        p[c] = v < mesh.positions.size() ? glm::vec3(model * glm::vec4(mesh.positions[v], 1.0f))
                                         : glm::vec3(0.0f);
      }
      if (mirrored) std::swap(p[1], p[2]);
      if (!isEmitterTriangle(material, glm::cross(p[1] - p[0], p[2] - p[0]))) continue;
      triangles.push_back({p[0], p[1], p[2], radiance, material.doubleSided,
                           static_cast<uint32_t>(i), mesh.material, material.bakeDirect});
    }
  }
  return triangles;
}

namespace {

using Polygon = std::vector<glm::dvec3>;

glm::dvec3 crossOf(const EmitterTriangle& e) {
  return glm::cross(glm::dvec3(e.v1 - e.v0), glm::dvec3(e.v2 - e.v0));
}

glm::dvec3 unitNormal(const EmitterTriangle& e) {
  const glm::dvec3 c = crossOf(e);
  const double l = glm::length(c);
  return l > 0.0 ? c / l : glm::dvec3(0.0);
}

// Vertices within kWeldDistance of each other are one vertex: a mesh's shared edges, and
// de-indexed triangles whose corners were computed two ways (rounding apart by ~1e-7 m).
constexpr double kWeldDistance = 1e-4;  // metres

class VertexWeld {
 public:
  uint32_t id(glm::vec3 p) {
    const glm::dvec3 q(p);
    const glm::ivec3 cell(glm::floor(q / kWeldDistance));
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = cells_.find(key(cell + glm::ivec3(dx, dy, dz)));
          if (it == cells_.end()) continue;
          for (const uint32_t v : it->second)
            if (glm::length(points_[v] - q) <= kWeldDistance) return v;
        }
    const auto v = static_cast<uint32_t>(points_.size());
    points_.push_back(q);
    cells_[key(cell)].push_back(v);
    return v;
  }

 private:
  // A cell's key: its three 21-bit coordinates packed (the scene's input limit, 1e6 m, is 1e10
  // cells of 0.1 mm: the key wraps there, which only costs a distance test, never a wrong weld).
  static uint64_t key(glm::ivec3 c) {
    const auto bits = [](int v) {
      return static_cast<uint64_t>(static_cast<uint32_t>(v)) & 0x1fffff;
    };
    return bits(c.x) | bits(c.y) << 21 | bits(c.z) << 42;
  }
  std::vector<glm::dvec3> points_;
  // Hashed, not ordered: a million emissive triangles weld 3 million corners, 27 cell lookups
  // each (an ordered map took 31 s of the 77 s set-up of tests/bench/make_million_emitters.py
  // --scatter).
  std::unordered_map<uint64_t, std::vector<uint32_t>> cells_;
};

using EdgeKey = std::pair<uint32_t, uint32_t>;
EdgeKey edgeOf(uint32_t a, uint32_t b) {
  return a < b ? EdgeKey{a, b} : EdgeKey{b, a};
}

// Triangles of one (instance, material) grown into connected, nearly planar pieces.
std::vector<std::vector<uint32_t>> planarPieces(const std::vector<EmitterTriangle>& all,
                                                const std::vector<uint32_t>& group, double minCos) {
  VertexWeld weld;
  std::vector<std::array<EdgeKey, 3>> sides(group.size());
  std::map<EdgeKey, std::vector<uint32_t>> edges;  // edge -> positions in `group`
  for (uint32_t g = 0; g < group.size(); ++g) {
    const EmitterTriangle& e = all[group[g]];
    const uint32_t a = weld.id(e.v0), b = weld.id(e.v1), c = weld.id(e.v2);
    sides[g] = {edgeOf(a, b), edgeOf(b, c), edgeOf(c, a)};
    for (const EdgeKey& k : sides[g]) edges[k].push_back(g);
  }
  std::vector<uint8_t> taken(group.size(), 0);
  std::vector<std::vector<uint32_t>> pieces;
  for (uint32_t seed = 0; seed < group.size(); ++seed) {
    if (taken[seed]) continue;
    const glm::dvec3 seedNormal = unitNormal(all[group[seed]]);
    std::vector<uint32_t> piece{seed}, frontier{seed};
    taken[seed] = 1;
    while (!frontier.empty()) {
      const uint32_t g = frontier.back();
      frontier.pop_back();
      for (const EdgeKey& k : sides[g])
        for (const uint32_t n : edges[k]) {
          if (taken[n] || glm::dot(unitNormal(all[group[n]]), seedNormal) < minCos) continue;
          taken[n] = 1;
          piece.push_back(n);
          frontier.push_back(n);
        }
    }
    std::sort(piece.begin(), piece.end());
    for (uint32_t& g : piece) g = group[g];
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

// The unit eigenvector of the larger eigenvalue of the symmetric 2×2 matrix [a b; b c].
glm::dvec2 majorAxis(double a, double b, double c) {
  const double angle = 0.5 * std::atan2(2.0 * b, a - c);
  return {std::cos(angle), std::sin(angle)};
}

// Keeps the part of `poly` where dot(axis, x) ≥ offset (Sutherland–Hodgman, one plane).
Polygon clipAbove(const Polygon& poly, glm::dvec3 axis, double offset) {
  Polygon out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const glm::dvec3 a = poly[i], b = poly[(i + 1) % poly.size()];
    const double da = glm::dot(axis, a) - offset, db = glm::dot(axis, b) - offset;
    if (da >= 0.0) out.push_back(a);
    if ((da >= 0.0) != (db >= 0.0)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return out;
}

// Cuts one planar piece on a grid along its in-plane principal axes into cells at most
// `maxExtent` long; returns the cells' triangles (each cell's own list, none empty).
std::vector<std::vector<EmitterTriangle>> gridCells(const std::vector<EmitterTriangle>& piece,
                                                    double maxExtent) {
  glm::dvec3 normal(0.0);
  for (const EmitterTriangle& e : piece) normal += crossOf(e);
  const double nl = glm::length(normal);
  if (nl <= 0.0 || !(maxExtent > 0.0)) return {piece};
  normal /= nl;
  const glm::dvec3 t = std::abs(normal.x) < 0.9 ? glm::normalize(glm::cross(normal, {1, 0, 0}))
                                                : glm::normalize(glm::cross(normal, {0, 1, 0}));
  const glm::dvec3 b = glm::cross(normal, t);
  // Second moments of area in the (t, b) plane about the piece's centroid: for a triangle,
  // ∫ x xᵀ dA = A/12 · (Σ v_i v_iᵀ + (Σ v_i)(Σ v_i)ᵀ).
  double area = 0.0;
  glm::dvec2 first(0.0);
  double stt = 0, stb = 0, sbb = 0;
  for (const EmitterTriangle& e : piece) {
    const double a = 0.5 * glm::length(crossOf(e));
    glm::dvec2 v[3], sum(0.0);
    const glm::vec3 corners[3] = {e.v0, e.v1, e.v2};
    for (int i = 0; i < 3; ++i) {
      v[i] = {glm::dot(t, glm::dvec3(corners[i])), glm::dot(b, glm::dvec3(corners[i]))};
      sum += v[i];
    }
    double mtt = sum.x * sum.x, mtb = sum.x * sum.y, mbb = sum.y * sum.y;
    for (const glm::dvec2& w : v) {
      mtt += w.x * w.x;
      mtb += w.x * w.y;
      mbb += w.y * w.y;
    }
    stt += a / 12.0 * mtt;
    stb += a / 12.0 * mtb;
    sbb += a / 12.0 * mbb;
    first += a * sum / 3.0;
    area += a;
  }
  if (area <= 0.0) return {piece};
  const glm::dvec2 mean = first / area;
  const glm::dvec2 major = majorAxis(stt / area - mean.x * mean.x, stb / area - mean.x * mean.y,
                                     sbb / area - mean.y * mean.y);
  const glm::dvec3 axes[2] = {major.x * t + major.y * b, -major.y * t + major.x * b};
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (const EmitterTriangle& e : piece)
    for (const glm::vec3& p : {e.v0, e.v1, e.v2})
      for (int k = 0; k < 2; ++k) {
        lo[k] = std::min(lo[k], glm::dot(axes[k], glm::dvec3(p)));
        hi[k] = std::max(hi[k], glm::dot(axes[k], glm::dvec3(p)));
      }
  int cells[2];
  for (int k = 0; k < 2; ++k)
    cells[k] = std::max(1, static_cast<int>(std::ceil((hi[k] - lo[k]) / maxExtent - 1e-4)));
  if (cells[0] * cells[1] == 1) return {piece};
  std::vector<std::vector<EmitterTriangle>> out;
  for (int i = 0; i < cells[0]; ++i)
    for (int j = 0; j < cells[1]; ++j) {
      const double w0 = (hi[0] - lo[0]) / cells[0], w1 = (hi[1] - lo[1]) / cells[1];
      std::vector<EmitterTriangle> cell;
      for (const EmitterTriangle& e : piece) {
        Polygon poly{glm::dvec3(e.v0), glm::dvec3(e.v1), glm::dvec3(e.v2)};
        // The first and last cells reach to infinity, so rounding never drops a sliver.
        if (i > 0) poly = clipAbove(poly, axes[0], lo[0] + i * w0);
        if (i + 1 < cells[0]) poly = clipAbove(poly, -axes[0], -(lo[0] + (i + 1) * w0));
        if (j > 0) poly = clipAbove(poly, axes[1], lo[1] + j * w1);
        if (j + 1 < cells[1]) poly = clipAbove(poly, -axes[1], -(lo[1] + (j + 1) * w1));
        for (std::size_t k = 1; k + 1 < poly.size(); ++k) {
          EmitterTriangle part = e;
          part.v0 = glm::vec3(poly[0]);
          part.v1 = glm::vec3(poly[k]);
          part.v2 = glm::vec3(poly[k + 1]);
          if (glm::length(glm::cross(part.v1 - part.v0, part.v2 - part.v0)) > 0.0f)
            cell.push_back(part);
        }
      }
      if (!cell.empty()) out.push_back(std::move(cell));
    }
  return out;
}

void describe(AreaLight& light, const std::vector<EmitterTriangle>& triangles) {
  glm::dvec3 weighted(0.0), normal(0.0), flux(0.0);
  double area = 0.0;
  for (uint32_t t = light.first; t < light.first + light.count; ++t) {
    const EmitterTriangle& e = triangles[t];
    const glm::dvec3 cross = crossOf(e);
    const double a = 0.5 * glm::length(cross);
    weighted += a * glm::dvec3(e.v0 + e.v1 + e.v2) / 3.0;
    normal += 0.5 * cross;
    area += a;
    // A Lambertian emitter of radiance L and area A emits π·L·A per face.
    flux += std::numbers::pi * a * glm::dvec3(e.radiance) * (e.doubleSided ? 2.0 : 1.0);
  }
  light.area = static_cast<float>(area);
  light.centre = area > 0.0 ? glm::vec3(weighted / area) : triangles[light.first].v0;
  const double length = glm::length(normal);
  light.normal = length > 1e-6 * area ? glm::vec3(normal / length) : glm::vec3(0.0f);
  light.flux = glm::vec3(flux);
  light.radius = 0.0f;
  for (uint32_t t = light.first; t < light.first + light.count; ++t)
    for (const glm::vec3& v : {triangles[t].v0, triangles[t].v1, triangles[t].v2})
      light.radius = std::max(light.radius, glm::length(v - light.centre));
}

}  // namespace

AreaLightSet splitAreaLights(const std::vector<EmitterTriangle>& triangles,
                             std::span<const Mobility> mobility, const AreaLightRule& rule) {
  const auto mobilityOf = [&](uint32_t instance) {
    return instance < mobility.size() ? mobility[instance] : Mobility::Static;
  };
  // (instance, material) groups in order of first appearance, static instances' first.
  std::vector<std::vector<uint32_t>> groups;
  std::map<std::pair<uint32_t, uint32_t>, std::size_t> groupOf;
  for (const Mobility pass : {Mobility::Static, Mobility::Dynamic})
    for (uint32_t t = 0; t < triangles.size(); ++t) {
      const EmitterTriangle& e = triangles[t];
      if (mobilityOf(e.instance) != pass) continue;
      const auto [it, added] = groupOf.try_emplace({e.instance, e.material}, groups.size());
      if (added) groups.emplace_back();
      groups[it->second].push_back(t);
    }
  const double minCos = std::cos(static_cast<double>(rule.planarDegrees) * std::numbers::pi / 180);
  AreaLightSet set;
  for (const std::vector<uint32_t>& group : groups)
    for (const std::vector<uint32_t>& piece : planarPieces(triangles, group, minCos)) {
      std::vector<EmitterTriangle> own;
      for (const uint32_t t : piece) own.push_back(triangles[t]);
      for (std::vector<EmitterTriangle>& cell : gridCells(own, rule.maxExtent)) {
        AreaLight light;
        light.first = static_cast<uint32_t>(set.triangles.size());
        light.count = static_cast<uint32_t>(cell.size());
        light.instance = cell.front().instance;
        light.material = cell.front().material;
        light.mobility = mobilityOf(light.instance);
        light.doubleSided = cell.front().doubleSided;
        light.bakeDirect = cell.front().bakeDirect;
        double cumulative = 0.0;
        for (const EmitterTriangle& e : cell) {
          cumulative += 0.5 * glm::length(crossOf(e));
          set.triangles.push_back(e);
          set.cumulativeArea.push_back(static_cast<float>(cumulative));
        }
        describe(light, set.triangles);
        set.lights.push_back(light);
      }
    }
  return set;
}

AreaLightSet sceneAreaLights(const Scene& scene, std::span<const glm::mat4> transforms,
                             const AreaLightRule& rule) {
  std::vector<Mobility> mobility;
  for (const Instance& instance : scene.instances) mobility.push_back(instance.mobility);
  return splitAreaLights(emitterTriangles(scene, transforms), mobility, rule);
}

std::vector<uint32_t> pickShadowedAreaLights(const std::vector<AreaLight>& lights,
                                             int maxShadowed) {
  std::vector<uint32_t> order(lights.size());
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  const auto total = [&](uint32_t i) {
    return lights[i].flux.r + lights[i].flux.g + lights[i].flux.b;
  };
  std::stable_sort(order.begin(), order.end(),
                   [&](uint32_t a, uint32_t b) { return total(a) > total(b); });
  order.resize(std::min(order.size(), static_cast<std::size_t>(std::max(maxShadowed, 0))));
  return order;
}

namespace {

// The radical inverse in base 2 (van der Corput): the second Hammersley coordinate.
double radicalInverse2(uint32_t i) {
  uint32_t bits = i;
  bits = (bits << 16u) | (bits >> 16u);
  bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
  bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
  bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
  bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
  return static_cast<double>(bits) * 0x1p-32;
}

}  // namespace

glm::vec3 pointOnLight(const AreaLightSet& set, std::size_t light, glm::vec2 u) {
  const AreaLight& l = set.lights[light];
  const auto begin = set.cumulativeArea.begin() + l.first;
  const auto end = begin + l.count;
  const double total = *(end - 1);
  double x = std::clamp(static_cast<double>(u.x), 0.0, 1.0) * total;
  const std::size_t i = static_cast<std::size_t>(
      std::min<std::ptrdiff_t>(std::upper_bound(begin, end, x) - begin, l.count - 1));
  const double lo = i == 0 ? 0.0 : begin[static_cast<std::ptrdiff_t>(i) - 1];
  x = std::clamp((x - lo) / std::max(begin[static_cast<std::ptrdiff_t>(i)] - lo, 1e-30), 0.0, 1.0);
  const double v = std::clamp(static_cast<double>(u.y), 0.0, 1.0);
  // Uniform over the triangle: barycentrics (1 − √x, √x(1 − v), √x·v).
  const double sx = std::sqrt(x);
  const EmitterTriangle& e = set.triangles[l.first + i];
  return glm::vec3((1.0 - sx) * glm::dvec3(e.v0) + sx * (1.0 - v) * glm::dvec3(e.v1) +
                   sx * v * glm::dvec3(e.v2));
}

std::vector<glm::vec3> samplePoints(const AreaLightSet& set, std::size_t light, int count) {
  std::vector<glm::vec3> points;
  for (int k = 0; k < count; ++k)
    points.push_back(pointOnLight(set, light,
                                  {static_cast<float>((k + 0.5) / count),
                                   static_cast<float>(radicalInverse2(static_cast<uint32_t>(k)))}));
  return points;
}

}  // namespace bounce
