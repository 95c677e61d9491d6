// A cache of irradiance that the path tracer may end its paths at (PathTracer::setCache), of one
// of two kinds:
//   indirect  at a vertex y reached after at least one reflection, the light leaving y after two
//             or more reflections there is ρ(y)/π·E_indirect(y), with E_indirect (W/m², per
//             linear-RGB channel) the irradiance at y from light that reflected at least once;
//             the tracer adds that term, keeps y's next-event estimate and the emission y's
//             BRDF-sampled ray finds, and ends the path (the delivered lightmap, read by probes);
//   total     (holdsDirect) the light leaving y after one or more reflections there is
//             ρ(y)/π·E_total(y), E_total the irradiance at y by every path, direct light too; the
//             tracer adds it and ends the path at y (the texels' cache pass).
// Where reading the cache would be wrong (the implementation's guards), the path goes on as
// without a cache. GL-free.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "trace/surface_point.h"

namespace bounce {

class IndirectCache {
 public:
  virtual ~IndirectCache() = default;
  // E_indirect or E_total (W/m²) at `at`, the hit of a ray from `from`, as seen from the ray's
  // side; nullopt where the cache cannot answer for that hit. Called from several threads at once.
  virtual std::optional<glm::vec3> irradianceAt(const SurfacePoint& at, glm::vec3 from) const = 0;
  // True when the cache holds E_total(y), every light's direct irradiance at y as well: the
  // tracer then adds ρ(y)/π·E_total(y) and ends the path at y, with no next-event estimate and
  // no BRDF-sampled ray there.
  virtual bool holdsDirect() const { return false; }
};

}  // namespace bounce
