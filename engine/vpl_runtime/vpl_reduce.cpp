#include "vpl_runtime/vpl_reduce.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "image/luminance.h"

namespace bounce {
namespace {

double weight(const Vpl& v) {
  return luminance(glm::dvec3(v.flux));
}

// 0..5: the dominant axis of the normal and its sign.
int normalGroup(glm::vec3 n) {
  const glm::vec3 a = glm::abs(n);
  const int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
  return 2 * axis + (n[axis] < 0.0f ? 1 : 0);
}

struct Cluster {
  std::vector<uint32_t> members;
  glm::dvec3 lo{0.0}, hi{0.0};
  double score = 0.0;  // luminance(Φ) · extent²

  void measure(std::span<const Vpl> vpls) {
    lo = glm::dvec3(std::numeric_limits<double>::max());
    hi = -lo;
    double flux = 0.0;
    for (uint32_t i : members) {
      lo = glm::min(lo, glm::dvec3(vpls[i].position));
      hi = glm::max(hi, glm::dvec3(vpls[i].position));
      flux += weight(vpls[i]);
    }
    const glm::dvec3 e = hi - lo;
    score = members.size() > 1 ? std::max(flux, 1e-300) * glm::dot(e, e) : -1.0;
  }
};

}  // namespace

Vpl mergeVpls(std::span<const Vpl> vpls, std::span<const uint32_t> members) {
  glm::dvec3 flux(0.0), position(0.0), normal(0.0), plain(0.0);
  double total = 0.0;
  for (uint32_t i : members) {
    const Vpl& v = vpls[i];
    const double w = weight(v);
    flux += glm::dvec3(v.flux);
    position += w * glm::dvec3(v.position);
    plain += glm::dvec3(v.position);
    normal += std::max(w, 1e-30) * glm::dvec3(v.normal);
    total += w;
  }
  Vpl out;
  out.flux = glm::vec3(flux);
  out.position =
      glm::vec3(total > 0.0 ? position / total : plain / static_cast<double>(members.size()));
  const double len = glm::length(normal);
  out.normal = len > 0.0 ? glm::vec3(normal / len) : vpls[members.front()].normal;
  return out;
}

std::vector<std::vector<uint32_t>> groupVpls(std::span<const Vpl> vpls, std::size_t k) {
  if (vpls.empty()) return {};
  std::vector<Cluster> clusters(6);
  for (uint32_t i = 0; i < vpls.size(); ++i)
    clusters[normalGroup(vpls[i].normal)].members.push_back(i);
  std::erase_if(clusters, [](const Cluster& c) { return c.members.empty(); });
  for (Cluster& c : clusters) c.measure(vpls);

  while (clusters.size() < k) {
    const auto worst =
        std::max_element(clusters.begin(), clusters.end(),
                         [](const Cluster& a, const Cluster& b) { return a.score < b.score; });
    if (worst->score <= 0.0) break;  // every cluster is a single point
    Cluster& c = *worst;
    const glm::dvec3 e = c.hi - c.lo;
    const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
    std::stable_sort(c.members.begin(), c.members.end(), [&](uint32_t a, uint32_t b) {
      return vpls[a].position[axis] < vpls[b].position[axis];
    });
    // Cut where the cumulative flux crosses half, keeping both sides non-empty.
    double total = 0.0;
    for (uint32_t i : c.members) total += weight(vpls[i]);
    double running = 0.0;
    std::size_t cut = 1;
    for (; cut < c.members.size() - 1; ++cut) {
      running += weight(vpls[c.members[cut - 1]]);
      if (running >= 0.5 * total) break;
    }
    Cluster right;
    right.members.assign(c.members.begin() + static_cast<std::ptrdiff_t>(cut), c.members.end());
    c.members.resize(cut);
    c.measure(vpls);
    right.measure(vpls);
    clusters.push_back(std::move(right));
  }
  std::vector<std::vector<uint32_t>> out;
  out.reserve(clusters.size());
  for (Cluster& c : clusters) out.push_back(std::move(c.members));
  return out;
}

std::vector<Vpl> reduceVpls(std::span<const Vpl> vpls, std::size_t k) {
  if (k >= vpls.size()) return {vpls.begin(), vpls.end()};
  std::vector<Vpl> out;
  for (const std::vector<uint32_t>& members : groupVpls(vpls, k))
    out.push_back(mergeVpls(vpls, members));
  return out;
}

}  // namespace bounce
