#include "render/cascades.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

namespace bounce {

std::vector<float> cascadeSplits(float znear, float zfar, int count, float lambda) {
  count = std::clamp(count, 1, kMaxCascades);
  std::vector<float> splits(static_cast<std::size_t>(count) + 1);
  const double n = znear, f = zfar;
  for (int i = 0; i <= count; ++i) {
    const double t = static_cast<double>(i) / count;
    const double logarithmic = n * std::pow(f / n, t);
    const double uniform = n + (f - n) * t;
    splits[static_cast<std::size_t>(i)] =
        static_cast<float>(lambda * logarithmic + (1.0 - lambda) * uniform);
  }
  splits.front() = znear;  // exact ends, whatever the rounding of pow
  splits.back() = zfar;
  return splits;
}

glm::dmat3 lightRotation(glm::vec3 lightDirection) {
  const glm::dvec3 z = -glm::normalize(glm::dvec3(lightDirection));
  // x horizontal (perpendicular to world up); a light straight down takes world x.
  const glm::dvec3 up = std::abs(z.y) > 0.999 ? glm::dvec3(0, 0, -1) : glm::dvec3(0, 1, 0);
  const glm::dvec3 x = glm::normalize(glm::cross(up, z));
  const glm::dvec3 y = glm::cross(z, x);
  return glm::transpose(glm::dmat3(x, y, z));  // rows x, y, z: world → light
}

namespace {

glm::dvec3 cameraPosition(const Camera& camera) {
  return glm::dvec3(camera.position());
}
glm::dvec3 cameraForward(const Camera& camera) {
  return glm::dvec3(camera.forward());
}

}  // namespace

glm::vec2 coveredDepthRange(const Camera& camera, const Bounds& bounds) {
  if (bounds.empty) return {camera.znear, camera.zfar};
  const glm::dvec3 o = cameraPosition(camera), forward = cameraForward(camera);
  double hi = std::numeric_limits<double>::lowest();
  for (int c = 0; c < 8; ++c) {
    const glm::dvec3 corner((c & 1) ? bounds.hi.x : bounds.lo.x,
                            (c & 2) ? bounds.hi.y : bounds.lo.y,
                            (c & 4) ? bounds.hi.z : bounds.lo.z);
    hi = std::max(hi, glm::dot(corner - o, forward));
  }
  // Rounded up to a power of 2^(1/4): the splits, hence the boxes' sizes, change only when the
  // scene's far end moves by 19%, not with every step of the camera.
  const double far = std::exp2(std::ceil(std::log2(std::max(hi, 1e-6)) * 4.0) / 4.0);
  const float f = std::min(camera.zfar, static_cast<float>(far));
  if (!(f > camera.znear * 1.001f)) return {camera.znear, camera.zfar};  // scene behind the camera
  return {camera.znear, f};
}

std::vector<glm::dvec3> frustumSliceCorners(const Camera& camera, float aspect, double nearDepth,
                                            double farDepth) {
  const double tanY = std::tan(0.5 * static_cast<double>(camera.yfov));
  const double tanX = tanY * aspect;
  const glm::dmat4 toWorld(camera.cameraToWorld);
  std::vector<glm::dvec3> corners;
  for (const double depth : {nearDepth, farDepth})
    for (const double sy : {-1.0, 1.0})
      for (const double sx : {-1.0, 1.0})
        corners.emplace_back(toWorld *
                             glm::dvec4(sx * tanX * depth, sy * tanY * depth, -depth, 1.0));
  return corners;
}

std::vector<Cascade> fitCascades(const Camera& camera, float aspect, glm::vec3 lightDirection,
                                 const Bounds& bounds, const CascadeSettings& settings) {
  const glm::vec2 range = coveredDepthRange(camera, bounds);
  const int count = std::clamp(settings.count, 1, kMaxCascades);
  const std::vector<float> splits = cascadeSplits(range.x, range.y, count, settings.splitLambda);
  const double blend = std::clamp(static_cast<double>(settings.blendFraction), 0.0, 0.5);
  const int resolution = std::max(settings.resolution, 2);
  const glm::dmat3 rotation = lightRotation(lightDirection);
  const glm::dvec3 lightAxis = glm::normalize(glm::dvec3(lightDirection));
  const double tanY = std::tan(0.5 * static_cast<double>(camera.yfov));
  const double k2 = tanY * tanY * (1.0 + static_cast<double>(aspect) * aspect);  // tan²x + tan²y

  std::vector<Cascade> cascades(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    Cascade& c = cascades[static_cast<std::size_t>(i)];
    const auto at = [&](int k) { return static_cast<double>(splits[static_cast<std::size_t>(k)]); };
    const double n = i == 0 ? at(0) : at(i) - blend * (at(i) - at(i - 1));
    const double f = at(i + 1);
    c.nearDepth = static_cast<float>(n);
    c.splitDepth = static_cast<float>(f);
    c.blendStart = i + 1 < count ? static_cast<float>(f - blend * (f - at(i))) : c.splitDepth;

    // The slice's smallest enclosing sphere, centred on the view axis at depth zc where the near
    // and far corners are equally far ((zc−n)² + n²k² = (f−zc)² + f²k²), or at the far plane when
    // that lies beyond it. Computed in camera space, so its radius ignores the camera's pose.
    const double zc = std::min((n + f) * (1.0 + k2) * 0.5, f);
    const double radius =
        std::sqrt(std::max((f - zc) * (f - zc) + f * f * k2, (zc - n) * (zc - n) + n * n * k2)) *
        (1.0 + 1e-6);
    const glm::dvec3 centre = cameraPosition(camera) + cameraForward(camera) * zc;
    const glm::dvec3 centreLight = rotation * centre;
    c.centre = centre;
    c.radius = radius;

    // Snap: texel size chosen so that a box of `resolution` texels starting at the snapped corner
    // (up to one texel below centre − radius) still reaches centre + radius.
    c.texelSize = 2.0 * radius / (resolution - 1);
    c.boxSide = c.texelSize * resolution;
    c.boxMin = glm::floor((glm::dvec2(centreLight) - radius) / c.texelSize) * c.texelSize;

    // Depth along the light: every caster and receiver lies in the scene's bounds, so their
    // depth range (fixed per light: no camera move changes the stored depths) is enough. Without
    // bounds, the slice's sphere, rounded outwards to whole box sides.
    double lo = 0.0, hi = 0.0;
    if (bounds.empty) {
      const double centreDepth = glm::dot(centre, lightAxis);
      lo = std::floor((centreDepth - radius) / c.boxSide) * c.boxSide;
      hi = std::ceil((centreDepth + radius) / c.boxSide) * c.boxSide;
    } else {
      lo = std::numeric_limits<double>::max();
      hi = std::numeric_limits<double>::lowest();
      for (int k = 0; k < 8; ++k) {
        const glm::dvec3 corner((k & 1) ? bounds.hi.x : bounds.lo.x,
                                (k & 2) ? bounds.hi.y : bounds.lo.y,
                                (k & 4) ? bounds.hi.z : bounds.lo.z);
        lo = std::min(lo, glm::dot(corner, lightAxis));
        hi = std::max(hi, glm::dot(corner, lightAxis));
      }
    }
    c.depthNear = lo - c.texelSize;
    c.depthFar = hi + c.texelSize;

    const glm::dmat4 view(rotation);
    // Light space looks down −z, so a point at depth d along the light has z = −d.
    const glm::dmat4 projection = glm::ortho(c.boxMin.x, c.boxMin.x + c.boxSide, c.boxMin.y,
                                             c.boxMin.y + c.boxSide, c.depthNear, c.depthFar);
    c.lightView = glm::mat4(view);
    c.projection = glm::mat4(projection);
    c.worldToClip = glm::mat4(projection * view);
  }
  return cascades;
}

}  // namespace bounce
