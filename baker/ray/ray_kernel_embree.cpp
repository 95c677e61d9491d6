#include "ray/ray_kernel_embree.h"

#include <pmmintrin.h>
#include <xmmintrin.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "ray/ray_validity.h"
#include "ray/triangle_checks.h"

namespace bounce {
namespace {

// Embree asks for flush-to-zero and denormals-are-zero on every thread that traces; MXCSR is
// per thread, so each thread sets it once on its first query.
void ensureFlushToZero() {
  thread_local const bool set = [] {
    _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
    _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
    return true;
  }();
  (void)set;
}

void throwOnDeviceError(RTCDevice device, const char* what) {
  const RTCError error = rtcGetDeviceError(device);
  if (error != RTC_ERROR_NONE)
    throw std::runtime_error(std::string("Embree: ") + what + " failed (error " +
                             std::to_string(static_cast<int>(error)) + ")");
}

void toRtcRay(const Ray& ray, RTCRay& r) {
  r.org_x = ray.origin.x;
  r.org_y = ray.origin.y;
  r.org_z = ray.origin.z;
  r.tnear = ray.tmin;
  r.dir_x = ray.direction.x;
  r.dir_y = ray.direction.y;
  r.dir_z = ray.direction.z;
  r.time = 0.0f;
  r.tfar = ray.tmax;
  r.mask = 0xffffffffu;
  r.id = 0;
  r.flags = 0;
}

}  // namespace

EmbreeKernel::EmbreeKernel(const WorldGeometry& geometry) : geometry_(geometry) {
  ensureFlushToZero();
  device_ = rtcNewDevice(nullptr);
  if (!device_) throw std::runtime_error("Embree: rtcNewDevice failed");
  try {
    fill();
  } catch (...) {
    if (scene_) rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
    throw;
  }
}

EmbreeKernel::~EmbreeKernel() {
  rtcReleaseScene(scene_);
  rtcReleaseDevice(device_);
}

void EmbreeKernel::fill() {
  scene_ = rtcNewScene(device_);
  throwOnDeviceError(device_, "rtcNewScene");
  // ROBUST keeps Embree's triangle test watertight on shared edges (tested with rays aimed
  // at the edges and vertices of closed meshes); static scene, medium build quality.
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_MEDIUM);

  const std::size_t triangleCount = geometry_.triangles.size();
  const std::size_t vertexCount = geometry_.positions.size();
  if (triangleCount > 0 && vertexCount > 0) {
    // Degenerate triangles must never hit: leave them out of the scene.
    bool allKept = true;
    for (std::size_t t = 0; t < triangleCount && allKept; ++t)
      allKept = isHittableTriangle(geometry_, t);
    const void* indices = geometry_.triangles.data();
    std::size_t keptCount = triangleCount;
    if (!allKept) {
      for (std::size_t t = 0; t < triangleCount; ++t) {
        if (!isHittableTriangle(geometry_, t)) continue;
        keptTriangles_.push_back(geometry_.triangles[t]);
        keptToWorld_.push_back(static_cast<uint32_t>(t));
      }
      indices = keptTriangles_.data();
      keptCount = keptTriangles_.size();
    }

    const float* positions = &geometry_.positions.data()->x;
    if (geometry_.positions.capacity() == vertexCount) {  // no room for the last 16-byte load
      paddedPositions_.assign(positions, positions + 3 * vertexCount);
      paddedPositions_.resize(3 * vertexCount + 4, 0.0f);
      positions = paddedPositions_.data();
    }

    if (keptCount > 0) {
      RTCGeometry mesh = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
      rtcSetSharedGeometryBuffer(mesh, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, positions, 0,
                                 sizeof(glm::vec3), vertexCount);
      rtcSetSharedGeometryBuffer(mesh, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, indices, 0,
                                 sizeof(glm::uvec3), keptCount);
      rtcCommitGeometry(mesh);
      rtcAttachGeometry(scene_, mesh);
      rtcReleaseGeometry(mesh);  // the scene holds it now
      throwOnDeviceError(device_, "building the triangle geometry");
    }
  }
  rtcCommitScene(scene_);
  throwOnDeviceError(device_, "rtcCommitScene");
}

Hit EmbreeKernel::toHit(unsigned primID, float t, float u, float v) const {
  Hit hit;
  hit.t = t;
  hit.triangle = keptToWorld_.empty() ? primID : keptToWorld_[primID];
  hit.u = u;
  hit.v = v;
  // Our convention, (p1−p0)×(p2−p0) normalized, from our own vertices: Embree's Ng has the
  // opposite orientation and no unit length.
  hit.geometricNormal = glm::normalize(geometry_.triangleCross(hit.triangle));
  return hit;
}

Hit EmbreeKernel::intersect(const Ray& ray) const {
  if (!isTraceable(ray)) return {};
  ensureFlushToZero();
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rayHit;
  toRtcRay(ray, rayHit.ray);
  rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayHit.hit.primID = RTC_INVALID_GEOMETRY_ID;
  rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &rayHit);
  if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return {};
  return toHit(rayHit.hit.primID, rayHit.ray.tfar, rayHit.hit.u, rayHit.hit.v);
}

bool EmbreeKernel::occluded(const Ray& ray) const {
  if (!isTraceable(ray)) return false;
  ensureFlushToZero();
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay r;
  toRtcRay(ray, r);
  rtcOccluded1(scene_, &context, &r);
  return r.tfar < 0.0f;  // Embree sets tfar = −∞ on occlusion
}

namespace {
constexpr std::size_t kPacket = 8;

template <typename Packet>
void fillPacket(std::span<const Ray> rays, std::size_t first, int (&valid)[kPacket], Packet& p) {
  for (std::size_t k = 0; k < kPacket; ++k) {
    const std::size_t i = first + k;
    const bool active = i < rays.size() && isTraceable(rays[i]);
    valid[k] = active ? -1 : 0;
    const Ray ray = active ? rays[i] : Ray{};  // inactive lanes still hold finite values
    p.org_x[k] = ray.origin.x;
    p.org_y[k] = ray.origin.y;
    p.org_z[k] = ray.origin.z;
    p.tnear[k] = ray.tmin;
    p.dir_x[k] = ray.direction.x;
    p.dir_y[k] = ray.direction.y;
    p.dir_z[k] = ray.direction.z;
    p.time[k] = 0.0f;
    p.tfar[k] = ray.tmax;
    p.mask[k] = 0xffffffffu;
    p.id[k] = static_cast<unsigned>(k);
    p.flags[k] = 0;
  }
}
}  // namespace

void EmbreeKernel::intersect(std::span<const Ray> rays, std::span<Hit> hits) const {
  if (hits.size() != rays.size())
    throw std::invalid_argument("EmbreeKernel::intersect: size mismatch");
  ensureFlushToZero();
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  for (std::size_t first = 0; first < rays.size(); first += kPacket) {
    alignas(32) int valid[kPacket];
    alignas(32) RTCRayHit8 packet;
    fillPacket(rays, first, valid, packet.ray);
    for (std::size_t k = 0; k < kPacket; ++k) {
      packet.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
      packet.hit.primID[k] = RTC_INVALID_GEOMETRY_ID;
      packet.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
    }
    rtcIntersect8(valid, scene_, &context, &packet);
    const std::size_t count = std::min(kPacket, rays.size() - first);
    for (std::size_t k = 0; k < count; ++k) {
      hits[first + k] =
          valid[k] && packet.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID
              ? toHit(packet.hit.primID[k], packet.ray.tfar[k], packet.hit.u[k], packet.hit.v[k])
              : Hit{};
    }
  }
}

void EmbreeKernel::occluded(std::span<const Ray> rays, std::span<uint8_t> occluded) const {
  if (occluded.size() != rays.size())
    throw std::invalid_argument("EmbreeKernel::occluded: size mismatch");
  ensureFlushToZero();
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  for (std::size_t first = 0; first < rays.size(); first += kPacket) {
    alignas(32) int valid[kPacket];
    alignas(32) RTCRay8 packet;
    fillPacket(rays, first, valid, packet);
    rtcOccluded8(valid, scene_, &context, &packet);
    const std::size_t count = std::min(kPacket, rays.size() - first);
    for (std::size_t k = 0; k < count; ++k)
      occluded[first + k] = valid[k] && packet.tfar[k] < 0.0f ? 1 : 0;
  }
}

}  // namespace bounce
