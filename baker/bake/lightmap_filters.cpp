#include "bake/lightmap_filters.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include <tbb/parallel_for.h>

#include "bake/texel_coverage.h"
#include "trace/sampling.h"

namespace bounce {

std::vector<uint32_t> labelCharts(int width, int height, const std::vector<uint8_t>& mask) {
  std::vector<uint32_t> label(mask.size(), 0);
  uint32_t next = 0;
  std::vector<std::size_t> stack;
  for (std::size_t start = 0; start < mask.size(); ++start) {
    if (!mask[start] || label[start] != 0) continue;
    label[start] = ++next;
    stack.push_back(start);
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      const int x = static_cast<int>(i % static_cast<std::size_t>(width));
      const int y = static_cast<int>(i / static_cast<std::size_t>(width));
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
          const std::size_t j = static_cast<std::size_t>(ny) * width + nx;
          if (mask[j] && label[j] == 0) {
            label[j] = next;
            stack.push_back(j);
          }
        }
      }
    }
  }
  return label;
}

std::size_t dilateOnce(Image& image, std::vector<uint8_t>& filled,
                       const std::vector<uint32_t>* labels) {
  const int w = image.width, h = image.height;
  // Each row's new texels found in parallel from the image as it was, then all written.
  std::vector<std::vector<std::pair<std::size_t, glm::vec3>>> newly(static_cast<std::size_t>(h));
  tbb::parallel_for(0, h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      const std::size_t i = image.index(x, y);
      if (filled[i]) continue;
      glm::vec3 sum(0.0f);
      int count = 0;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
          const std::size_t j = image.index(nx, ny);
          if (!filled[j]) continue;
          if (labels != nullptr && (*labels)[j] != (*labels)[i]) continue;
          sum += image.pixels[j];
          ++count;
        }
      }
      if (count > 0)
        newly[static_cast<std::size_t>(y)].emplace_back(i, sum / static_cast<float>(count));
    }
  });
  std::size_t added = 0;
  for (const auto& row : newly)
    for (const auto& [i, value] : row) {
      image.pixels[i] = value;
      filled[i] = 1;
      ++added;
    }
  return added;
}

std::size_t fillUnresolvedZeros(Image& image, const std::vector<uint8_t>& unresolved,
                                const std::vector<uint8_t>& invalid,
                                const std::vector<uint32_t>& labels,
                                std::vector<float>& relativeError, int rings) {
  // dilateOnce fills texels with filled == 0 from filled neighbours of their label. Invalid
  // texels hold no value yet: label 0 keeps them out as sources, filled = 1 out as targets.
  std::vector<uint8_t> filled(unresolved.size());
  std::vector<uint32_t> sources = labels;
  for (std::size_t t = 0; t < unresolved.size(); ++t) {
    filled[t] = unresolved[t] ? 0 : 1;
    if (invalid[t]) sources[t] = 0;
  }
  std::size_t total = 0;
  for (int ring = 0; ring < rings; ++ring) {
    const std::size_t added = dilateOnce(image, filled, &sources);
    if (added == 0) break;
    total += added;
  }
  for (std::size_t t = 0; t < filled.size(); ++t)
    if (unresolved[t] && filled[t]) relativeError[t] = 1.0f;
  return total;
}

glm::vec3 bilinear(const Image& image, glm::vec2 p) {
  const glm::vec2 q = p - 0.5f;
  const int x0 = static_cast<int>(std::floor(q.x)), y0 = static_cast<int>(std::floor(q.y));
  const float fx = q.x - static_cast<float>(x0), fy = q.y - static_cast<float>(y0);
  auto at = [&](int x, int y) {
    return image.at(std::clamp(x, 0, image.width - 1), std::clamp(y, 0, image.height - 1));
  };
  return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) +
         fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
}

namespace {

// The 4 texels and weights of a bilinear lookup (clamped), as bilinear() uses them.
struct Footprint {
  std::array<std::size_t, 4> texel;
  std::array<float, 4> weight;
};

Footprint footprint(const Image& image, glm::vec2 p) {
  const glm::vec2 q = p - 0.5f;
  const int x0 = static_cast<int>(std::floor(q.x)), y0 = static_cast<int>(std::floor(q.y));
  const float fx = q.x - static_cast<float>(x0), fy = q.y - static_cast<float>(y0);
  auto index = [&](int x, int y) {
    return image.index(std::clamp(x, 0, image.width - 1), std::clamp(y, 0, image.height - 1));
  };
  return {{index(x0, y0), index(x0 + 1, y0), index(x0, y0 + 1), index(x0 + 1, y0 + 1)},
          {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy}};
}

glm::vec3 lookup(const Image& image, const Footprint& f) {
  glm::vec3 v(0.0f);
  for (int k = 0; k < 4; ++k) v += f.weight[k] * image.pixels[f.texel[k]];
  return v;
}

// Kaczmarz step for one seam point: with the residual r = lookup(a) − lookup(b) = Σ c_k·x_k
// (c = +weight under a, −weight under b, merged where a texel is under both), the orthogonal
// projection onto r = 0: x_k −= r·c_k / Σ c². Cyclic sweeps of it converge to the nearest
// texel values (least change) at which every pair agrees.
void project(Image& image, const Footprint& a, const Footprint& b) {
  std::array<std::size_t, 8> texel;
  std::array<float, 8> coef;
  int n = 0;
  auto add = [&](std::size_t t, float c) {
    for (int k = 0; k < n; ++k)
      if (texel[k] == t) {
        coef[k] += c;
        return;
      }
    texel[n] = t;
    coef[n++] = c;
  };
  for (int k = 0; k < 4; ++k) add(a.texel[k], a.weight[k]);
  for (int k = 0; k < 4; ++k) add(b.texel[k], -b.weight[k]);
  float norm2 = 0.0f;
  glm::vec3 residual(0.0f);
  for (int k = 0; k < n; ++k) {
    norm2 += coef[k] * coef[k];
    residual += coef[k] * image.pixels[texel[k]];
  }
  if (!(norm2 > 0.0f)) return;
  for (int k = 0; k < n; ++k) image.pixels[texel[k]] -= residual * (coef[k] / norm2);
}

std::vector<std::pair<Footprint, Footprint>> seamPoints(const Image& image,
                                                        const std::vector<Seam>& seams) {
  std::vector<std::pair<Footprint, Footprint>> points;
  for (const Seam& s : seams) {
    const float length = std::max(glm::length(s.a1 - s.a0), glm::length(s.b1 - s.b0));
    const int n = std::max(2, static_cast<int>(std::ceil(2.0f * length)) + 1);
    for (int i = 0; i < n; ++i) {
      const float t = (static_cast<float>(i) + 0.5f) / static_cast<float>(n);
      points.emplace_back(footprint(image, glm::mix(s.a0, s.a1, t)),
                          footprint(image, glm::mix(s.b0, s.b1, t)));
    }
  }
  return points;
}

using EdgeKey = std::array<int64_t, 6>;

std::array<int64_t, 3> quantize(glm::vec3 p) {
  return {std::llround(static_cast<double>(p.x) * 1e5),
          std::llround(static_cast<double>(p.y) * 1e5),
          std::llround(static_cast<double>(p.z) * 1e5)};
}

struct EdgeSide {
  glm::vec2 uv0, uv1;  // texel space, at the edge's first and second key point
  glm::vec3 n0, n1;
  bool crossed = false;  // another surface crosses this one here (Mesh::cutEdges bit k + 3)
};

}  // namespace

float stitchSeams(Image& image, const std::vector<Seam>& seams, int iterations, bool clampAtZero) {
  const auto points = seamPoints(image, seams);
  for (int it = 0; it < iterations; ++it) {
    for (const auto& [a, b] : points) project(image, a, b);
  }
  // Irradiance is non-negative: a nudge may not push a texel below zero.
  if (clampAtZero)
    for (glm::vec3& p : image.pixels) p = glm::max(p, glm::vec3(0.0f));
  float worst = 0.0f;
  for (const auto& [a, b] : points) {
    const float la = luminance(lookup(image, a)), lb = luminance(lookup(image, b));
    const float scale = std::max(la, lb);
    if (scale > 0.0f) worst = std::max(worst, std::abs(la - lb) / scale);
  }
  return worst;
}

float largestSeamJump(const Image& image, const std::vector<Seam>& seams) {
  float worst = 0.0f;
  for (const auto& [a, b] : seamPoints(image, seams))
    worst = std::max(worst, std::abs(luminance(lookup(image, a)) - luminance(lookup(image, b))));
  return worst;
}

std::vector<Seam> findSeams(const Scene& scene, const WorldGeometry& geometry,
                            const LightmapLayout& layout) {
  const glm::vec2 size(static_cast<float>(layout.width), static_cast<float>(layout.height));
  const std::vector<InstanceBase> bases = instanceBases(scene);
  std::map<EdgeKey, std::vector<EdgeSide>> edges;
  for (const InstanceLightmapUv& region : layout.instances) {
    if (region.instance >= scene.instances.size()) continue;
    const Mesh& mesh = scene.meshes[scene.instances[region.instance].mesh];
    if (region.cornerUv.size() != mesh.indices.size()) continue;
    for (std::size_t c = 0; c < mesh.indices.size(); ++c) {
      const std::size_t t = c / 3, k = c % 3, next = 3 * t + (k + 1) % 3;
      const uint32_t v0 = bases[region.instance].vertex + mesh.indices[c];
      const uint32_t v1 = bases[region.instance].vertex + mesh.indices[next];
      auto q0 = quantize(geometry.positions[v0]), q1 = quantize(geometry.positions[v1]);
      EdgeSide side{region.cornerUv[c] * size, region.cornerUv[next] * size, geometry.normals[v0],
                    geometry.normals[v1]};
      side.crossed = !mesh.cutEdges.empty() && (mesh.cutEdges[t] & (8u << k)) != 0;
      if (q1 < q0) {
        std::swap(q0, q1);
        std::swap(side.uv0, side.uv1);
        std::swap(side.n0, side.n1);
      }
      if (q0 == q1) continue;  // degenerate edge
      edges[{q0[0], q0[1], q0[2], q1[0], q1[1], q1[2]}].push_back(side);
    }
  }
  std::vector<Seam> seams;
  for (const auto& [key, sides] : edges) {
    for (std::size_t i = 0; i < sides.size(); ++i) {
      for (std::size_t j = i + 1; j < sides.size(); ++j) {
        const EdgeSide &a = sides[i], &b = sides[j];
        if (a.crossed || b.crossed) continue;  // a wall between them: the light differs
        if (glm::dot(a.n0, b.n0) < 0.99f || glm::dot(a.n1, b.n1) < 0.99f) continue;
        const float apart = std::max(glm::length(a.uv0 - b.uv0), glm::length(a.uv1 - b.uv1));
        if (apart < 1e-3f) continue;  // the same atlas edge: bilinear already agrees
        seams.push_back({a.uv0, a.uv1, b.uv0, b.uv1});
      }
    }
  }
  return seams;
}

void denoise(Image& image, const DenoiseGuide& guide, Image* alongside) {
  static constexpr float kStop = 2.0f;
  static constexpr std::array<float, 5> kB3 = {1.0f / 16, 1.0f / 4, 3.0f / 8, 1.0f / 4, 1.0f / 16};
  const int w = image.width, h = image.height;
  // Variance of each texel's luminance, (W/m²)²: the sampler's estimate, then carried through
  // each pass as a weighted mean's variance, Σ w_j²·var_j / (Σ w_j)² (independent texels), so a
  // later, wider pass only merges differences that the noise left after the earlier ones cannot
  // explain.
  std::vector<float> variance(image.pixels.size(), 0.0f);
  for (std::size_t i = 0; i < variance.size(); ++i) {
    const float sigma = guide.relativeError[i] * luminance(image.pixels[i]);
    variance[i] = sigma * sigma;
  }
  Image next = image;
  Image nextAlongside = alongside ? *alongside : Image();
  std::vector<float> nextVariance = variance;
  for (const int step : {1, 2, 4, 8}) {
    if (step > 1 && static_cast<float>(step) * guide.texelSize > guide.maxStepMetres) break;
    // Position tolerance grows with the step so that the kernel's reach is not cut off.
    const float sigmaPosition = static_cast<float>(step) * guide.texelSize;
    const float invTwoSigma2 =
        sigmaPosition > 0.0f ? 1.0f / (2 * sigmaPosition * sigmaPosition) : 0;
    // Rows in parallel: each texel reads the last pass's values and writes only its own.
    tbb::parallel_for(0, h, [&](int y) {
      for (int x = 0; x < w; ++x) {
        const std::size_t i = image.index(x, y);
        if (guide.label[i] == 0) continue;
        const float li = luminance(image.pixels[i]);
        // A texel no light reaches (every sample exactly 0) is exact: nothing to denoise, and
        // light from a neighbour across a thin wall must not blur into it.
        if (li == 0.0f && variance[i] == 0.0f) continue;
        glm::vec3 sum(0.0f), sumAlongside(0.0f);
        float weightSum = 0.0f, weight2Variance = 0.0f;
        for (int dy = -2; dy <= 2; ++dy) {
          for (int dx = -2; dx <= 2; ++dx) {
            const int nx = x + dx * step, ny = y + dy * step;
            if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
            const std::size_t j = image.index(nx, ny);
            if (guide.label[j] != guide.label[i]) continue;
            const float cosine = glm::dot(guide.normal[i], guide.normal[j]);
            if (cosine <= 0.0f) continue;
            const glm::vec3 dp = guide.position[i] - guide.position[j];
            float weight = kB3[dx + 2] * kB3[dy + 2] * std::pow(cosine, 32.0f) *
                           std::exp(-glm::dot(dp, dp) * invTwoSigma2);
            // Luminance edge-stopping at kStop combined standard errors: a difference the noise
            // cannot explain is a real gradient (a shadow, a corner) and is kept.
            const float lj = luminance(image.pixels[j]);
            const float sigma2 = kStop * kStop * (variance[i] + variance[j]);
            const float dl = li - lj;
            if (sigma2 > 0.0f)
              weight *= std::exp(-dl * dl / (2.0f * sigma2));
            else if (dl != 0.0f)
              weight = 0.0f;
            sum += weight * image.pixels[j];
            if (alongside) sumAlongside += weight * alongside->pixels[j];
            weightSum += weight;
            weight2Variance += weight * weight * variance[j];
          }
        }
        if (weightSum > 0.0f) {
          next.pixels[i] = sum / weightSum;
          if (alongside) nextAlongside.pixels[i] = sumAlongside / weightSum;
          nextVariance[i] = weight2Variance / (weightSum * weightSum);
        }
      }
    });
    image = next;
    if (alongside) *alongside = nextAlongside;
    variance = nextVariance;
  }
}

}  // namespace bounce
