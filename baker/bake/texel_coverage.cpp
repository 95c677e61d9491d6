#include "bake/texel_coverage.h"

#include "atlas/uv_geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include <tbb/parallel_for.h>

#include "trace/sampling.h"
#include "trace/sobol_sampler.h"

namespace bounce {

namespace {

float cross2(glm::vec2 a, glm::vec2 b) {
  return a.x * b.y - a.y * b.x;
}

// One triangle's atlas image (texel space, counter-clockwise) and its world vertices.
struct TriangleImage {
  std::array<glm::vec2, 3> uv;
  std::array<uint32_t, 3> vertex;  // WorldGeometry vertex of each corner, same order as uv
  uint32_t triangle = 0;
};

// A triangle's part of one texel: a convex polygon in texel space.
struct Fragment {
  uint32_t texel = 0;
  uint32_t image = 0;  // index into the TriangleImage list
  uint8_t count = 0;
  std::array<glm::vec2, 8> polygon;
};

}  // namespace

std::vector<InstanceBase> instanceBases(const Scene& scene) {
  std::vector<InstanceBase> bases(scene.instances.size());
  InstanceBase next;
  for (std::size_t i = 0; i < scene.instances.size(); ++i) {
    const Mesh& mesh = scene.meshes.at(scene.instances[i].mesh);
    bases[i] = next;
    next.triangle += static_cast<uint32_t>(mesh.indices.size() / 3);
    next.vertex += static_cast<uint32_t>(mesh.positions.size());
  }
  return bases;
}

namespace {

// Triangles one task clips into fragments (blocks of one region, in order).
constexpr std::size_t kTrianglesPerBlock = 4096;

// One block's triangle images and their fragments (image indices within the block).
struct ClippedBlock {
  std::vector<TriangleImage> images;
  std::vector<Fragment> fragments;
};

// Triangles [from, to) of `region`'s mesh clipped against the texels their images touch.
ClippedBlock clipBlock(const Mesh& mesh, const InstanceLightmapUv& region, InstanceBase base,
                       std::size_t from, std::size_t to, int width, int height) {
  const glm::vec2 size(static_cast<float>(width), static_cast<float>(height));
  ClippedBlock block;
  for (std::size_t t = from; t < to; ++t) {
    TriangleImage image;
    image.triangle = base.triangle + static_cast<uint32_t>(t);
    for (int k = 0; k < 3; ++k) {
      image.uv[k] = region.cornerUv[3 * t + k] * size;
      image.vertex[k] = base.vertex + mesh.indices[3 * t + k];
    }
    if (!(std::abs(cross2(image.uv[1] - image.uv[0], image.uv[2] - image.uv[0])) > 0.0f))
      continue;  // no area in the atlas: nothing to bake
    const auto imageIndex = static_cast<uint32_t>(block.images.size());
    block.images.push_back(image);
    const glm::vec2 lo = glm::min(image.uv[0], glm::min(image.uv[1], image.uv[2]));
    const glm::vec2 hi = glm::max(image.uv[0], glm::max(image.uv[1], image.uv[2]));
    const int x0 = std::max(0, static_cast<int>(std::floor(lo.x)));
    const int y0 = std::max(0, static_cast<int>(std::floor(lo.y)));
    const int x1 = std::min(width - 1, static_cast<int>(std::floor(hi.x)));
    const int y1 = std::min(height - 1, static_cast<int>(std::floor(hi.y)));
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const glm::vec2 texelMin(static_cast<float>(x), static_cast<float>(y));
        const std::vector<glm::vec2> poly =
            clipTriangleToBox(image.uv[0], image.uv[1], image.uv[2], texelMin, texelMin + 1.0f);
        if (poly.size() < 3 || !(polygonArea(poly) > 0.0f)) continue;
        Fragment f;
        f.texel = static_cast<uint32_t>(y * width + x);
        f.image = imageIndex;
        f.count = static_cast<uint8_t>(std::min<std::size_t>(poly.size(), f.polygon.size()));
        std::copy_n(poly.begin(), f.count, f.polygon.begin());
        block.fragments.push_back(f);
      }
    }
  }
  return block;
}

// Fan triangles of one texel's polygons, with their cumulative areas.
struct TexelFan {
  struct Triangle {
    glm::vec2 a, b, c;
    uint32_t image;
  };
  std::vector<Triangle> triangles;
  std::vector<float> cumulative;
  float total = 0.0f;  // texel²
};

TexelFan fanOf(const Fragment* fragment, const Fragment* end) {
  TexelFan fan;
  for (; fragment != end; ++fragment)
    for (int i = 1; i + 1 < fragment->count; ++i) {
      const TexelFan::Triangle tri{fragment->polygon[0], fragment->polygon[i],
                                   fragment->polygon[i + 1], fragment->image};
      const float area = 0.5f * std::abs(cross2(tri.b - tri.a, tri.c - tri.a));
      if (!(area > 0.0f)) continue;
      fan.total += area;
      fan.triangles.push_back(tri);
      fan.cumulative.push_back(fan.total);
    }
  return fan;
}

// The texel's points (at most pointsPerTexel) written from `out`; returns how many.
std::size_t samplePoints(const TexelFan& fan, std::size_t texel, int pointsPerTexel, uint32_t seed,
                         const std::vector<TriangleImage>& images, const WorldGeometry& geometry,
                         TexelPoint* out) {
  std::size_t written = 0;
  SobolSampler sampler(seed, static_cast<uint32_t>(texel));
  for (int s = 0; s < pointsPerTexel; ++s) {
    sampler.startSample(static_cast<uint32_t>(s));
    glm::vec2 u = sampler.get2D();
    // Pick a fan triangle by area with u.x, then reuse u.x's position inside its interval.
    const float target = u.x * fan.total;
    const std::size_t k = std::min<std::size_t>(
        static_cast<std::size_t>(
            std::upper_bound(fan.cumulative.begin(), fan.cumulative.end(), target) -
            fan.cumulative.begin()),
        fan.triangles.size() - 1);
    const float lo = k == 0 ? 0.0f : fan.cumulative[k - 1];
    u.x = std::clamp((target - lo) / (fan.cumulative[k] - lo), 0.0f, 0.99999994f);
    const TexelFan::Triangle& tri = fan.triangles[k];
    const glm::vec2 bary = sampleUniformTriangle(u);
    const glm::vec2 q = (1.0f - bary.x - bary.y) * tri.a + bary.x * tri.b + bary.y * tri.c;
    // Barycentrics of q in the mesh triangle's atlas image → world point and normal.
    const TriangleImage& image = images[tri.image];
    const glm::vec2 e1 = image.uv[1] - image.uv[0], e2 = image.uv[2] - image.uv[0];
    const float det = cross2(e1, e2);
    const float w1 = std::clamp(cross2(q - image.uv[0], e2) / det, 0.0f, 1.0f);
    const float w2 = std::clamp(cross2(e1, q - image.uv[0]) / det, 0.0f, 1.0f - w1);
    const float w0 = 1.0f - w1 - w2;
    TexelPoint point;
    point.position = w0 * geometry.positions[image.vertex[0]] +
                     w1 * geometry.positions[image.vertex[1]] +
                     w2 * geometry.positions[image.vertex[2]];
    const glm::vec3 cross = geometry.triangleCross(image.triangle);
    const float crossLength = glm::length(cross);
    if (!(crossLength > 0.0f) || !std::isfinite(crossLength)) continue;  // degenerate in 3D
    point.geometricNormal = cross / crossLength;
    glm::vec3 n = w0 * geometry.normals[image.vertex[0]] + w1 * geometry.normals[image.vertex[1]] +
                  w2 * geometry.normals[image.vertex[2]];
    const float nLength = glm::length(n);
    n = nLength > 0.0f ? n / nLength : point.geometricNormal;
    // The shading normal lies on the front face's side (as SurfacePoint's invariant).
    point.shadingNormal = glm::dot(n, point.geometricNormal) > 0.0f ? n : point.geometricNormal;
    point.texelPosition = q;
    point.triangle = image.triangle;
    out[written++] = point;
  }
  return written;
}

}  // namespace

// Every step runs in parallel and is laid out in a fixed order (blocks of triangles in layout
// order; texels in index order), so the coverage is the same bytes at any thread count.
TexelCoverage buildTexelCoverage(const Scene& scene, const WorldGeometry& geometry,
                                 const LightmapLayout& layout, int pointsPerTexel, uint32_t seed) {
  if (layout.width < 1 || layout.height < 1)
    throw std::invalid_argument("lightmap layout has no texels");
  if (pointsPerTexel < 1) throw std::invalid_argument("pointsPerTexel must be at least 1");

  const std::vector<InstanceBase> bases = instanceBases(scene);
  if (scene.triangleCount() != geometry.triangleCount())
    throw std::invalid_argument("world geometry does not match the scene");

  // Each region's triangles in blocks: (region, first triangle, end).
  struct Block {
    std::size_t region = 0, from = 0, to = 0;
  };
  std::vector<Block> blocks;
  for (std::size_t r = 0; r < layout.instances.size(); ++r) {
    const InstanceLightmapUv& region = layout.instances[r];
    if (region.instance >= scene.instances.size())
      throw std::invalid_argument("lightmap layout names an instance the scene does not have");
    const Mesh& mesh = scene.meshes[scene.instances[region.instance].mesh];
    if (region.cornerUv.size() != mesh.indices.size())
      throw std::invalid_argument("lightmap layout of instance " + std::to_string(region.instance) +
                                  " does not have 3 UVs per triangle");
    for (std::size_t t = 0; t < mesh.triangleCount(); t += kTrianglesPerBlock)
      blocks.push_back({r, t, std::min(mesh.triangleCount(), t + kTrianglesPerBlock)});
  }
  std::vector<ClippedBlock> clipped(blocks.size());
  tbb::parallel_for(std::size_t{0}, blocks.size(), [&](std::size_t b) {
    const InstanceLightmapUv& region = layout.instances[blocks[b].region];
    clipped[b] = clipBlock(scene.meshes[scene.instances[region.instance].mesh], region,
                           bases[region.instance], blocks[b].from, blocks[b].to, layout.width,
                           layout.height);
  });

  TexelCoverage coverage;
  coverage.width = layout.width;
  coverage.height = layout.height;
  coverage.first.assign(coverage.texelCount() + 1, 0);
  coverage.coveredArea.assign(coverage.texelCount(), 0.0f);

  // The images one after another, and the fragments sorted by texel, stably (block order, then
  // each block's order), by counting: fragmentStart[texel] is the texel's first fragment.
  std::vector<TriangleImage> images;
  std::vector<uint32_t> fragmentStart(coverage.texelCount() + 1, 0);
  for (const ClippedBlock& block : clipped)
    for (const Fragment& f : block.fragments) ++fragmentStart[f.texel + 1];
  for (std::size_t texel = 0; texel < coverage.texelCount(); ++texel)
    fragmentStart[texel + 1] += fragmentStart[texel];
  std::vector<Fragment> fragments(fragmentStart.back());
  {
    std::vector<uint32_t> next(fragmentStart.begin(), fragmentStart.end() - 1);
    for (ClippedBlock& block : clipped) {
      const auto offset = static_cast<uint32_t>(images.size());
      images.insert(images.end(), block.images.begin(), block.images.end());
      for (Fragment f : block.fragments) {
        f.image += offset;
        fragments[next[f.texel]++] = f;
      }
      block = ClippedBlock{};
    }
  }

  // Texels with fragments, each given room for pointsPerTexel points in order (their count
  // bounds the points, so the list is allocated once: bake_memory.h); filled in parallel, then
  // closed up in texel order.
  std::vector<uint32_t> fragmentTexels;
  for (std::size_t texel = 0; texel < coverage.texelCount(); ++texel)
    if (fragmentStart[texel + 1] > fragmentStart[texel])
      fragmentTexels.push_back(static_cast<uint32_t>(texel));
  const auto perTexel = static_cast<std::size_t>(pointsPerTexel);
  coverage.points.resize(fragmentTexels.size() * perTexel);
  std::vector<uint32_t> written(fragmentTexels.size(), 0);
  tbb::parallel_for(std::size_t{0}, fragmentTexels.size(), [&](std::size_t j) {
    const uint32_t texel = fragmentTexels[j];
    const TexelFan fan =
        fanOf(&fragments[fragmentStart[texel]], &fragments[0] + fragmentStart[texel + 1]);
    if (fan.triangles.empty()) return;
    coverage.coveredArea[texel] = fan.total;
    written[j] = static_cast<uint32_t>(samplePoints(fan, texel, pointsPerTexel, seed, images,
                                                    geometry, &coverage.points[j * perTexel]));
  });
  std::size_t end = 0, j = 0;
  for (std::size_t texel = 0; texel < coverage.texelCount(); ++texel) {
    coverage.first[texel] = static_cast<uint32_t>(end);
    if (j < fragmentTexels.size() && fragmentTexels[j] == texel) {
      if (end != j * perTexel)  // moved down: the room before was as large or larger
        std::copy_n(coverage.points.begin() + static_cast<std::ptrdiff_t>(j * perTexel), written[j],
                    coverage.points.begin() + static_cast<std::ptrdiff_t>(end));
      end += written[j++];
    }
  }
  coverage.first[coverage.texelCount()] = static_cast<uint32_t>(end);
  coverage.points.resize(end);
  return coverage;
}

}  // namespace bounce
