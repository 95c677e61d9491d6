// Multi-bounce transport against exact answers: the furnace, light that arrives only after a
// bounce, and light through a slit (with the firefly clamp's bias).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "support/form_factors.h"

#include "transport_scenes.h"

namespace bounce {
namespace {

// Furnace: L = Le + ρ·L everywhere, so L = Le / (1 − ρ). Russian roulette is on (from 3
// reflections); max depth 200 truncates Σ_{k>200} ρ^k·Le = ρ^201/(1−ρ)·Le, i.e. 6e-10·Le
// for ρ = 0.9 (7e-61 for 0.5), far below the tolerance. Every pixel must lie within 5 of its
// standard errors (its own sample variance over 256 samples); the image mean within 5 of
// its standard error. The sample variance of scrambled-net samples overstates the error,
// so these bounds are conservative.
void furnaceTest(float albedo) {
  const glm::vec3 le(0.5f, 1.0f, 2.0f);
  test::World world = test::furnace(albedo, le);
  world.build();
  TraceSettings settings;
  settings.spp = 256;
  settings.maxDepth = 200;
  const CameraRender render = traceCamera(world.scene, world.geometry, *world.kernel,
                                          test::furnaceCamera(), 16, 16, settings);
  const glm::dvec3 expected = glm::dvec3(le) / (1.0 - static_cast<double>(albedo));
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 16; ++x) {
      const glm::dvec3 se = glm::sqrt(glm::dvec3(render.sampleVariance.at(x, y)) / 256.0);
      ASSERT_TRUE(test::agreeWithin(glm::dvec3(render.radiance.at(x, y)), se, expected,
                                    glm::dvec3(0.0), 5.0))
          << "pixel " << x << "," << y;
    }
  }
  const test::ImageMean mean = test::imageMean(render, 256);
  std::printf("furnace ρ = %.1f: mean %.4f (expected %.4f), SE %.2g, variance per sample %.3g\n",
              static_cast<double>(albedo), mean.mean.g, expected.g, mean.standardError.g,
              mean.variancePerSample.g);
  EXPECT_TRUE(test::agreeWithin(mean.mean, mean.standardError, expected, glm::dvec3(0.0), 5.0));
}

TEST(Transport, FurnaceAlbedoHalf) {
  furnaceTest(0.5f);
}
TEST(Transport, FurnaceAlbedoNineTenths) {
  furnaceTest(0.9f);
}

// Light reaching the visible surfaces only after a diffuse bounce: NEE + MIS and pure BRDF
// sampling are two unbiased estimators of the same image; their means agree within 5
// combined standard errors (independent seeds).
TEST(Transport, OneBounceLightAgreesBetweenMisAndBrdfSampling) {
  test::World world = test::corridor();
  world.build();
  TraceSettings mis;
  mis.spp = 128;
  mis.seed = 1;
  TraceSettings brdf = mis;
  brdf.strategy = LightStrategy::BrdfOnly;
  brdf.spp = 512;
  brdf.seed = 2;
  const Camera camera = test::corridorCamera();
  const auto a = traceCamera(world.scene, world.geometry, *world.kernel, camera, 16, 16, mis);
  const auto b = traceCamera(world.scene, world.geometry, *world.kernel, camera, 16, 16, brdf);
  const test::ImageMean ma = test::imageMean(a, mis.spp);
  const test::ImageMean mb = test::imageMean(b, brdf.spp);
  std::printf(
      "one bounce: MIS %.5f ± %.2g (variance/sample %.3g), BRDF-only %.5f ± %.2g "
      "(variance/sample %.3g)\n",
      ma.mean.g, ma.standardError.g, ma.variancePerSample.g, mb.mean.g, mb.standardError.g,
      mb.variancePerSample.g);
  EXPECT_GT(ma.mean.g, 0.0);
  EXPECT_TRUE(test::agreeWithin(ma.mean, ma.standardError, mb.mean, mb.standardError, 5.0));
  // Direct-only must see nothing here (no visible point sees the emitter), and
  // indirect-only must then equal the full image: the same samples give the same value.
  TraceSettings direct = mis;
  direct.paths = PathSet::DirectOnly;
  const auto d = traceCamera(world.scene, world.geometry, *world.kernel, camera, 16, 16, direct);
  for (const glm::vec3& p : d.radiance.pixels) ASSERT_EQ(p, glm::vec3(0.0f));
  TraceSettings indirect = mis;
  indirect.paths = PathSet::IndirectOnly;
  const auto i = traceCamera(world.scene, world.geometry, *world.kernel, camera, 16, 16, indirect);
  const test::ImageMean mi = test::imageMean(i, mis.spp);
  EXPECT_NEAR(mi.mean.g, ma.mean.g, 1e-5 * ma.mean.g);
}

// Form factor from the floor point (px, py, 0) (normal +z) to the part of the slit rooms'
// ceiling emitter seen through the slit (or all of it without the partition), by quadrature
// of the analytic integrand in double precision: dF = cosθ·cosθ'/(π r²) dA = h²/(π r⁴) dA
// for parallel planes h apart. For each emitter column qx the visible qy form an interval
// (the line from p to q crosses x = kSlitX at the fraction s = (px − kSlitX)/(px − qx) of
// the way, at y = py + s·(qy − py), which must lie in the slit), integrated in closed form:
// ∫ du/(a² + u²)² = u/(2a²(a² + u²)) + atan(u/a)/(2a³), a² = (qx − px)² + h². The qx
// integral is a midpoint rule with n columns (error O(1/n²) at the interval's kinks).
double slitFormFactor(double px, double py, bool withPartition, int n = 400) {
  const double x0 = test::kSlitLightX0, x1 = test::kSlitLightX1;
  const double h = test::kSlitLightZ;
  const double dx = (x1 - x0) / n;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double qx = x0 + (i + 0.5) * dx;
    double lo = test::kSlitLightY0, hi = test::kSlitLightY1;
    if (withPartition) {
      const double s = (px - test::kSlitX) / (px - qx);
      lo = std::max(lo, py + (test::kSlitY0 - py) / s);
      hi = std::min(hi, py + (test::kSlitY1 - py) / s);
      if (!(hi > lo)) continue;
    }
    const double a2 = (qx - px) * (qx - px) + h * h, a = std::sqrt(a2);
    const auto primitive = [&](double u) {
      return u / (2 * a2 * (a2 + u * u)) + std::atan(u / a) / (2 * a2 * a);
    };
    sum += (primitive(hi - py) - primitive(lo - py)) * dx;
  }
  return h * h / std::numbers::pi * sum;
}

// The exact image mean of a box-filtered render of the black slit rooms: ρ·Le·F averaged
// over the film, F at the floor point each film position's ray reaches (the view holds only
// the right room's floor), midpoint rule with `grid`² positions per pixel.
double slitImageMean(const Camera& camera, int size, double albedo, bool withPartition, int grid) {
  double sum = 0.0;
  for (int y = 0; y < size * grid; ++y) {
    for (int x = 0; x < size * grid; ++x) {
      const Ray ray = cameraRay(camera, size, size, (x + 0.5f) / static_cast<float>(grid),
                                (y + 0.5f) / static_cast<float>(grid));
      const double t = -static_cast<double>(ray.origin.z) / ray.direction.z;
      const double px = ray.origin.x + t * ray.direction.x;
      const double py = ray.origin.y + t * ray.direction.y;
      EXPECT_TRUE(t > 0 && px > test::kSlitX && px < 4 && py > 0 && py < 2) << px << "," << py;
      sum += albedo * test::kSlitLightLe * slitFormFactor(px, py, withPartition);
    }
  }
  return sum / (static_cast<double>(size * grid) * (size * grid));
}

// Light through a 2 cm slit against an independent closed form: with every surface black but
// the floor, the right floor's radiance is ρ·Le·F(visible emitter through the slit), computed
// by slitFormFactor. The render's image mean must agree with it within 5 standard errors
// (unbiased and finite despite most light samples being blocked). The quadrature is checked
// against the closed-form rectangle form factor (no partition: the whole emitter is seen)
// and against itself at 10× the columns. The variance per sample is printed
// (docs/path_tracer.md quotes it) next to that of the same view with the partition removed.
TEST(Transport, LightThroughASlitIsUnbiased) {
  for (const glm::dvec2 p : {glm::dvec2(2.7, 0.8), glm::dvec2(3.5, 1.3)}) {
    const double closed = test::parallelRectangleFormFactor(p.x, p.y, test::kSlitLightX0,
                                                            test::kSlitLightX1, test::kSlitLightY0,
                                                            test::kSlitLightY1, test::kSlitLightZ);
    EXPECT_NEAR(slitFormFactor(p.x, p.y, false), closed, 1e-5 * closed);
    const double coarse = slitFormFactor(p.x, p.y, true),
                 fine = slitFormFactor(p.x, p.y, true, 4000);
    EXPECT_GT(fine, 0.0);
    EXPECT_NEAR(coarse, fine, 1e-4 * fine);
  }
  const float albedo = 0.7f;
  const int size = 32;
  const Camera camera = test::slitFloorCamera();
  TraceSettings settings;
  settings.spp = 512;
  settings.seed = 11;
  double variance[2] = {0.0, 0.0}, mean[2] = {0.0, 0.0};
  for (bool withPartition : {true, false}) {
    test::World world = test::blackSlitRooms(withPartition, albedo);
    world.build();
    const auto r =
        traceCamera(world.scene, world.geometry, *world.kernel, camera, size, size, settings);
    EXPECT_TRUE(r.radiance.allFinite());
    EXPECT_EQ(r.nonFiniteSamples, 0u);
    const test::ImageMean m = test::imageMean(r, settings.spp);
    const double exact = slitImageMean(camera, size, albedo, withPartition, 4);
    std::printf(
        "%s: mean %.5f ± %.2g W/(sr·m²), exact %.5f (%+.2f%%); variance per sample %.4g "
        "(relative σ²/μ² = %.3g)\n",
        withPartition ? "slit" : "open room", m.mean.g, m.standardError.g, exact,
        100.0 * (m.mean.g / exact - 1.0), m.variancePerSample.g,
        m.variancePerSample.g / (exact * exact));
    EXPECT_GT(exact, 0.0);
    EXPECT_TRUE(test::agreeWithin(m.mean, m.standardError, glm::dvec3(exact), glm::dvec3(0.0), 5.0))
        << (withPartition ? "slit" : "open room");
    variance[withPartition ? 0 : 1] = m.variancePerSample.g / (exact * exact);
    mean[withPartition ? 0 : 1] = exact;
  }
  std::printf("slit: %.1f%% of the open room's light, %.0f× its relative variance per sample\n",
              100.0 * mean[0] / mean[1], variance[0] / variance[1]);
}

// The firefly clamp darkens: with the same samples, every clamped pixel is ≤ the unclamped
// one, and the clamped mean lies more than 5 combined standard errors below the unbiased
// long render. Its bias is printed (docs/path_tracer.md quotes it).
TEST(Transport, FireflyClampIsBiasedLow) {
  test::World world = test::slitRooms(true);
  world.build();
  const Camera camera = test::slitCamera();
  TraceSettings reference;
  reference.spp = 1024;
  reference.seed = 12;
  const auto r = traceCamera(world.scene, world.geometry, *world.kernel, camera, 16, 16, reference);
  const test::ImageMean mr = test::imageMean(r, reference.spp);

  TraceSettings plain;
  plain.spp = 64;
  plain.seed = 11;
  const auto p = traceCamera(world.scene, world.geometry, *world.kernel, camera, 16, 16, plain);
  const test::ImageMean mp = test::imageMean(p, plain.spp);
  // Clamp levels in multiples of the image's mean radiance; the strictest must be visibly
  // biased, and all darken pixel by pixel.
  for (double level : {2.0, 20.0, 200.0}) {
    TraceSettings clamped = plain;
    clamped.clampRadiance = static_cast<float>(level * mr.mean.g);
    const auto c = traceCamera(world.scene, world.geometry, *world.kernel, camera, 16, 16, clamped);
    for (std::size_t i = 0; i < p.radiance.pixels.size(); ++i) {
      for (int ch = 0; ch < 3; ++ch) {
        ASSERT_LE(c.radiance.pixels[i][ch], p.radiance.pixels[i][ch] * (1.0f + 1e-6f)) << i;
      }
    }
    const test::ImageMean mc = test::imageMean(c, clamped.spp);
    const double bias = mc.mean.g - mr.mean.g;
    const double se = std::sqrt(mc.standardError.g * mc.standardError.g +
                                mr.standardError.g * mr.standardError.g);
    std::printf(
        "clamp at %.4f W/(sr·m²) (%.0f× the mean): mean %.5f vs unbiased %.5f: bias "
        "%.5f (%.1f%% ± %.1f%%), variance per sample %.4g vs %.4g unclamped\n",
        static_cast<double>(clamped.clampRadiance), level, mc.mean.g, mr.mean.g, bias,
        100.0 * bias / mr.mean.g, 100.0 * se / mr.mean.g, mc.variancePerSample.g,
        mp.variancePerSample.g);
    if (level == 2.0) {
      EXPECT_LT(bias, -5.0 * se);
    }
  }
}

}  // namespace
}  // namespace bounce
