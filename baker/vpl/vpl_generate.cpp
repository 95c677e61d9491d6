#include "vpl/vpl_generate.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "scene/light_falloff.h"
#include "trace/emitters.h"
#include "trace/light_sampler.h"
#include "trace/sampling.h"
#include "trace/sobol_sampler.h"
#include "trace/surface_point.h"

namespace bounce {

namespace {

// Sampler dimensions (2D pairs) of path i (sample i of the pattern (seed, 0)).
constexpr uint32_t kDimLightPick = 0;       // light (CDF), then emitter triangle (alias)
constexpr uint32_t kDimLightOrigin = 1;     // point on the triangle / on the directional disc
constexpr uint32_t kDimLightDirection = 2;  // emission direction
constexpr uint32_t kDimFirstBounce = 3;     // then 2 per bounce: direction, roulette

bool finiteRay(const Ray& ray) {
  return isFinite(ray.origin) && isFinite(ray.direction) &&
         glm::dot(ray.direction, ray.direction) > 0.0f;
}

// Uniform direction in the cone of half-angle acos(cosMax) about +z: pdf = 1/(2π(1 − cosMax)).
glm::vec3 sampleUniformCone(glm::vec2 u, float cosMax) {
  const float cosTheta = 1.0f - u.x * (1.0f - cosMax);
  const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
  const float phi = 2.0f * kPi * u.y;
  return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

// A ray leaving a light with the flux it carries (β₀, W per channel, not yet divided by N).
struct Emission {
  Ray ray;
  glm::vec3 point{0.0f};  // the sampled point on the light (metres), before the ray offset
  glm::vec3 flux{0.0f};
  bool valid = false;
};

class PathStarter {
 public:
  PathStarter(const Scene& scene, const WorldGeometry& geometry)
      : scene_(scene), emitters_(scene, geometry), lights_(scene, geometry, emitters_, {}) {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const glm::vec3& p : geometry.positions) {
      if (!isFinite(p)) continue;
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    centre_ = 0.5f * (lo + hi);
  }
  bool empty() const { return lights_.empty(); }

  Emission start(SobolSampler& sampler) const {
    Emission e;
    sampler.setDimension(kDimLightPick);
    const glm::vec2 u = sampler.get2D();
    const LightPick pick = lights_.pick(u.x);
    if (!(pick.pmf > 0.0f)) return e;
    sampler.setDimension(kDimLightOrigin);
    const glm::vec2 origin = sampler.get2D();
    sampler.setDimension(kDimLightDirection);
    glm::vec2 dir = sampler.get2D();
    if (pick.kind == LightKind::Area) {
      const EmitterSample s = emitters_.sample({pick.remapped, u.y}, origin);
      glm::vec3 n = s.normal;
      float sidePmf = 1.0f;
      if (s.doubleSided) {  // pick a face with probability 1/2, reusing dir.x
        sidePmf = 0.5f;
        if (dir.x < 0.5f) {
          dir.x *= 2.0f;
        } else {
          dir.x = std::min((dir.x - 0.5f) * 2.0f, 0x1.fffffep-1f);
          n = -n;
        }
      }
      const glm::vec3 local = sampleCosineHemisphere(dir);
      if (!(local.z > 0.0f)) return e;
      e.ray.direction = Frame(n).toWorld(local);
      e.ray.origin = offsetRayOrigin(s.position, n, e.ray.direction);
      e.point = s.position;
      // β₀ = Le·cosθ / (pmf_set · p_A · side · cosθ/π) = π·Le / (pmf_set · p_A · side).
      e.flux = kPi * s.radiance / (pick.pmf * s.pdfArea * sidePmf);
    } else {
      const Light& light = scene_.lights[pick.index];
      if (light.type == LightType::Point) {
        // Uniform sphere: pdf 1/(4π).
        const float z = 1.0f - 2.0f * dir.x;
        const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        const float phi = 2.0f * kPi * dir.y;
        e.ray.origin = light.position;
        e.ray.direction = {r * std::cos(phi), r * std::sin(phi), z};
        e.flux = light.intensity * (4.0f * kPi / pick.pmf);
      } else if (light.type == LightType::Spot) {
        // Uniform in the outer cone: pdf 1/(2π(1 − cos outer)); I(ω) = I·falloff.
        const glm::vec3 axis = glm::normalize(light.direction);
        const float cosOuter = std::cos(std::clamp(light.outerConeAngle, 0.0f, kPi));
        const glm::vec3 local = sampleUniformCone(dir, cosOuter);
        e.ray.origin = light.position;
        e.ray.direction = Frame(axis).toWorld(local);
        e.flux = light.intensity * spotFalloff(light, local.z) *
                 (2.0f * kPi * (1.0f - cosOuter) / pick.pmf);
      } else {
        // Directional: a point uniform on the disc of radius R facing the light, R outside the
        // scene's bounding sphere: pdf 1/(πR²), β₀ = E·πR²/pmf.
        const float radius = lights_.sceneRadius();
        const glm::vec3 w = glm::normalize(light.direction);
        const glm::vec2 disc = radius * sampleConcentricDisk(origin);
        const Frame frame(w);
        e.ray.origin = centre_ - w * (1.01f * radius) + frame.t * disc.x + frame.b * disc.y;
        e.ray.direction = w;
        e.flux = light.irradiance * (kPi * radius * radius / pick.pmf);
      }
    }
    if (pick.kind != LightKind::Area) e.point = e.ray.origin;
    e.ray.tmin = 0.0f;
    e.ray.tmax = std::numeric_limits<float>::infinity();
    e.valid = finiteRay(e.ray) && isFinite(e.flux) && maxComponent(e.flux) > 0.0f;
    return e;
  }

 private:
  const Scene& scene_;
  EmitterTable emitters_;
  LightSampler lights_;
  glm::vec3 centre_{0.0f};
};

// The VPLs of one path, in bounce order (bounce k at index k − 1), flux not yet divided by N.
struct PathVpls {
  std::vector<Vpl> vpls;
};

PathVpls tracePath(const Scene& scene, const WorldGeometry& geometry, const RayKernel& kernel,
                   const PathStarter& starter, const VplSettings& settings, uint32_t index) {
  PathVpls out;
  SobolSampler sampler(settings.seed, 0u);
  sampler.startSample(index);
  const Emission emission = starter.start(sampler);
  if (!emission.valid) return out;
  Ray ray = emission.ray;
  glm::vec3 beta = emission.flux;   // flux arriving at the next hit
  glm::vec3 from = emission.point;  // where the segment to the next hit starts
  for (int bounce = 1; bounce <= settings.maxBounces; ++bounce) {
    const Hit hit = kernel.intersect(ray);
    if (!hit.valid()) break;
    SurfacePoint point;
    if (!makeSurfacePoint(scene, geometry, ray, hit, point)) break;
    // The VPL re-emits what the surface reflects: Φ = β·ρ (bake_folder/vpl.h).
    const glm::vec3 reflected = beta * point.albedo;
    if (!(maxComponent(reflected) > 0.0f) || !isFinite(reflected)) break;
    out.vpls.push_back({point.position, point.shadingNormal, reflected, from, index});
    from = point.position;

    const uint32_t dim = kDimFirstBounce + 2u * static_cast<uint32_t>(bounce - 1);
    beta = reflected;
    if (bounce >= settings.rouletteBounce) {
      const float survive = std::min(1.0f, maxComponent(point.albedo));
      sampler.setDimension(dim + 1);
      if (sampler.get1D() >= survive) break;
      beta /= survive;
    }
    // Lambertian reflection, cosine-weighted: f·cosθ/pdf = ρ, already in β.
    sampler.setDimension(dim);
    const glm::vec3 local = sampleCosineHemisphere(sampler.get2D());
    const glm::vec3 wi = Frame(point.shadingNormal).toWorld(local);
    if (!(local.z > 0.0f) || glm::dot(wi, point.geometricNormal) <= 0.0f) break;
    ray.origin = offsetRayOrigin(point.position, point.geometricNormal, wi);
    ray.direction = wi;
    ray.tmin = 0.0f;
    ray.tmax = std::numeric_limits<float>::infinity();
    if (!finiteRay(ray)) break;
  }
  return out;
}

}  // namespace

glm::dvec3 VplSet::totalFlux() const {
  glm::dvec3 sum(0.0);
  for (const glm::dvec3& f : fluxPerBounce) sum += f;
  return sum;
}

VplSet generateVpls(const Scene& scene, const WorldGeometry& geometry, const RayKernel& kernel,
                    const VplSettings& settings) {
  VplSet set;
  const int maxBounces = std::max(settings.maxBounces, 1);
  VplSettings s = settings;
  s.maxBounces = maxBounces;
  set.fluxPerBounce.assign(maxBounces, glm::dvec3(0.0));
  set.fluxPerBounceError.assign(maxBounces, glm::dvec3(0.0));
  const PathStarter starter(scene, geometry);
  if (starter.empty() || settings.maxVpls <= 0) return set;

  // Per-bounce sums of the path contributions and of their squares (unnormalised β·ρ).
  std::vector<glm::dvec3> sum(maxBounces, glm::dvec3(0.0)), sumSq(maxBounces, glm::dvec3(0.0));
  double totalSum = 0.0, totalSumSq = 0.0;
  const uint64_t maxPaths = 64ull * static_cast<uint64_t>(settings.maxVpls);
  tbb::task_arena arena(settings.threads > 0 ? settings.threads : tbb::task_arena::automatic);
  std::vector<PathVpls> batch(kVplBatch);
  bool full = false;
  while (!full && set.paths < maxPaths) {
    if (settings.progress) settings.progress->throwIfCancelled();
    const uint64_t first = set.paths;
    const std::size_t vplsBefore = set.vpls.size();
    arena.execute([&] {
      tbb::parallel_for(0, kVplBatch, [&](int i) {
        batch[i] = tracePath(scene, geometry, kernel, starter, s, static_cast<uint32_t>(first + i));
      });
    });
    // Kept in path order, so the set does not depend on the thread count.
    for (const PathVpls& path : batch) {
      if (set.vpls.size() + path.vpls.size() > static_cast<std::size_t>(settings.maxVpls)) {
        full = true;
        break;
      }
      double pathTotal = 0.0;
      for (std::size_t k = 0; k < path.vpls.size(); ++k) {
        const glm::dvec3 f(path.vpls[k].flux);
        sum[k] += f;
        sumSq[k] += f * f;
        pathTotal += static_cast<double>(luminance(path.vpls[k].flux));
        set.vpls.push_back(path.vpls[k]);
        set.bounce.push_back(static_cast<uint8_t>(k + 1));
      }
      totalSum += pathTotal;
      totalSumSq += pathTotal * pathTotal;
      ++set.paths;
    }
    if (settings.progress) settings.progress->advance(set.vpls.size() - vplsBefore, kVplBatch);
    const double n = static_cast<double>(set.paths);
    if (n > 1.0 && totalSum > 0.0) {
      const double varianceOfMean =
          std::max(0.0, totalSumSq - totalSum * totalSum / n) / (n * (n - 1.0));
      set.relativeError = std::sqrt(varianceOfMean) / (totalSum / n);
      if (set.paths >= static_cast<uint64_t>(settings.minPaths) &&
          set.relativeError <= settings.relativeError)
        break;
    }
  }
  // Φ = β·ρ / N: each path is one of N estimates of the light's whole emission.
  const double n = static_cast<double>(std::max<uint64_t>(set.paths, 1));
  for (Vpl& v : set.vpls) v.flux = glm::vec3(glm::dvec3(v.flux) / n);
  for (int k = 0; k < maxBounces; ++k) {
    set.fluxPerBounce[k] = sum[k] / n;
    const glm::dvec3 variance =
        glm::max(sumSq[k] - sum[k] * sum[k] / n, glm::dvec3(0.0)) / std::max(n - 1.0, 1.0);
    set.fluxPerBounceError[k] = glm::sqrt(variance / n);
  }
  return set;
}

}  // namespace bounce
