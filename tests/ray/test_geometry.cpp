#include "test_geometry.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

namespace bounce::testing {
namespace {

uint32_t addVertex(WorldGeometry& g, glm::vec3 p) {
  g.positions.push_back(p);
  return static_cast<uint32_t>(g.positions.size() - 1);
}

// A smooth pseudo-random field on the unit sphere: a sum of six random plane waves.
class Bumps {
 public:
  explicit Bumps(uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (Wave& w : waves_) w = Wave{glm::vec3(u(rng), u(rng), u(rng)) * 6.0f, 3.0f * u(rng)};
  }
  float operator()(glm::vec3 n) const {
    float sum = 0.0f;
    for (const Wave& w : waves_) sum += std::sin(glm::dot(w.k, n) + w.phase) / 6.0f;
    return sum;
  }

 private:
  struct Wave {
    glm::vec3 k;
    float phase;
  };
  Wave waves_[6];
};

}  // namespace

void addCube(WorldGeometry& g, const glm::mat4& transform) {
  const auto base = static_cast<uint32_t>(g.positions.size());
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 p((i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 1.0f : -1.0f);
    g.positions.push_back(glm::vec3(transform * glm::vec4(p, 1.0f)));
  }
  // Faces as quads (a, b, c, d) counter-clockwise seen from outside.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    g.triangles.push_back(base + glm::uvec3(q[0], q[1], q[2]));
    g.triangles.push_back(base + glm::uvec3(q[0], q[2], q[3]));
  }
}

void addIcosphere(WorldGeometry& g, int subdivisions, glm::vec3 centre, float radius) {
  const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
  std::vector<glm::vec3> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                              {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                              {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (auto& p : v) p = glm::normalize(p);
  std::vector<glm::uvec3> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                               {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                               {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                               {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;  // shared edges stay shared
    const auto mid = [&](uint32_t a, uint32_t b) {
      const auto key = std::minmax(a, b);
      const auto it = midpoints.find(key);
      if (it != midpoints.end()) return it->second;
      v.push_back(glm::normalize(v[a] + v[b]));
      return midpoints[key] = static_cast<uint32_t>(v.size() - 1);
    };
    std::vector<glm::uvec3> next;
    for (const glm::uvec3 tri : f) {
      const uint32_t a = mid(tri.x, tri.y), b = mid(tri.y, tri.z), c = mid(tri.z, tri.x);
      next.insert(next.end(), {{tri.x, a, c}, {tri.y, b, a}, {tri.z, c, b}, {a, b, c}});
    }
    f = std::move(next);
  }
  const auto base = static_cast<uint32_t>(g.positions.size());
  for (const glm::vec3 p : v) g.positions.push_back(centre + radius * p);
  for (const glm::uvec3 tri : f) g.triangles.push_back(base + tri);
}

void addDisplacedSphere(WorldGeometry& g, int rings, int segments, glm::vec3 centre, float radius,
                        float bumpiness, uint32_t seed) {
  const float pi = std::numbers::pi_v<float>;
  const Bumps bumps(seed);
  const uint32_t north = addVertex(g, centre + glm::vec3(0, radius, 0));
  const uint32_t south = addVertex(g, centre - glm::vec3(0, radius, 0));
  const auto firstRing = static_cast<uint32_t>(g.positions.size());
  for (int r = 1; r < rings; ++r) {
    const float theta = pi * static_cast<float>(r) / static_cast<float>(rings);
    for (int s = 0; s < segments; ++s) {
      const float phi = 2.0f * pi * static_cast<float>(s) / static_cast<float>(segments);
      const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                        std::sin(theta) * std::sin(phi));
      addVertex(g, centre + radius * (1.0f + bumpiness * bumps(n)) * n);
    }
  }
  const auto at = [&](int r, int s) {  // ring r in [1, rings − 1]
    return firstRing + static_cast<uint32_t>((r - 1) * segments + (s % segments));
  };
  for (int s = 0; s < segments; ++s) {
    g.triangles.push_back({north, at(1, s + 1), at(1, s)});
    g.triangles.push_back({south, at(rings - 1, s), at(rings - 1, s + 1)});
    for (int r = 1; r + 1 < rings; ++r) {
      g.triangles.push_back({at(r, s), at(r, s + 1), at(r + 1, s + 1)});
      g.triangles.push_back({at(r, s), at(r + 1, s + 1), at(r + 1, s)});
    }
  }
}

void addTriangleSoup(WorldGeometry& g, int count, glm::vec3 lower, glm::vec3 upper, float maxEdge,
                     uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int i = 0; i < count; ++i) {
    const glm::vec3 p0 = lower + (upper - lower) * glm::vec3(u(rng), u(rng), u(rng));
    const auto offset = [&] { return maxEdge * (glm::vec3(u(rng), u(rng), u(rng)) - 0.5f); };
    const uint32_t a = addVertex(g, p0);
    const uint32_t b = addVertex(g, p0 + offset());
    const uint32_t c = addVertex(g, p0 + offset());
    g.triangles.push_back({a, b, c});
  }
}

void finish(WorldGeometry& g) {
  g.normals.assign(g.positions.size(), glm::vec3(0, 1, 0));
  g.uv0.assign(g.positions.size(), glm::vec2(0));
  g.uv1.assign(g.positions.size(), glm::vec2(0));
  g.triangleMaterial.assign(g.triangles.size(), 0);
  g.triangleInstance.assign(g.triangles.size(), 0);
}

std::vector<Ray> cameraRays(glm::vec3 eye, glm::vec3 target, int width, int height) {
  const glm::vec3 forward = glm::normalize(target - eye);
  const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
  const glm::vec3 up = glm::cross(right, forward);
  const float halfHeight = std::tan(std::numbers::pi_v<float> / 6.0f);
  const float halfWidth = halfHeight * static_cast<float>(width) / static_cast<float>(height);
  std::vector<Ray> rays;
  rays.reserve(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float sx = (2.0f * (static_cast<float>(x) + 0.5f) / static_cast<float>(width) - 1.0f);
      const float sy = (1.0f - 2.0f * (static_cast<float>(y) + 0.5f) / static_cast<float>(height));
      const glm::vec3 d = forward + sx * halfWidth * right + sy * halfHeight * up;
      rays.push_back(Ray{eye, 0.0f, glm::normalize(d)});
    }
  return rays;
}

glm::vec3 cosineDirection(glm::vec3 n, float u1, float u2) {
  const float r = std::sqrt(u1), phi = 2.0f * std::numbers::pi_v<float> * u2;
  const glm::vec3 a = std::abs(n.x) > 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  const glm::vec3 tangent = glm::normalize(glm::cross(a, n));
  const glm::vec3 bitangent = glm::cross(n, tangent);
  const float z = std::sqrt(std::max(0.0f, 1.0f - u1));
  return glm::normalize(r * std::cos(phi) * tangent + r * std::sin(phi) * bitangent + z * n);
}

std::vector<Ray> surfaceRays(const WorldGeometry& g, std::size_t count, uint32_t seed,
                             float maxDistance) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::uniform_int_distribution<std::size_t> pick(0, g.triangles.size() - 1);
  std::vector<Ray> rays;
  rays.reserve(count);
  while (rays.size() < count) {
    const std::size_t t = pick(rng);
    const glm::vec3 cross = g.triangleCross(t);
    if (!(glm::dot(cross, cross) > 0.0f)) continue;
    glm::vec3 n = glm::normalize(cross);
    if (u(rng) < 0.5f) n = -n;
    float b1 = u(rng), b2 = u(rng);
    if (b1 + b2 > 1.0f) b1 = 1.0f - b1, b2 = 1.0f - b2;
    const glm::uvec3 tri = g.triangles[t];
    const glm::vec3 p =
        (1.0f - b1 - b2) * g.positions[tri.x] + b1 * g.positions[tri.y] + b2 * g.positions[tri.z];
    const glm::vec3 d = cosineDirection(n, u(rng), u(rng));
    Ray ray{offsetRayOrigin(p, n, d), 0.0f, d};
    if (maxDistance > 0.0f) ray.tmax = maxDistance * (1.0f - u(rng));
    rays.push_back(ray);
  }
  return rays;
}

}  // namespace bounce::testing
