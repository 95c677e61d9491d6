// The error of the map the bake delivers (denoised, filled, dilated, stitched), estimated per
// texel as one draw of that error, E_F − E: its noise from two independent halves of each
// texel's samples sent through the same filters as the map, plus the denoiser's bias and the
// adaptive stop's bias. bake.json's estimatedError and error.exr are its magnitude relative to
// E_F, which is what |E_F − E_converged| / E_converged measures (docs/baker.md).
//
// Split: sample s of texel i goes to half A or B by a hash of (seed, i, s) (splitSign: +1 A,
// −1 B), independent of the sample's value and of the sampler's pattern. (Not even and odd
// indices: the sampler's index shuffle ties index bit 0 to the top binary digit of every
// dimension pair's first coordinate (sobol_sampler.h), so the even samples of a texel pick
// points from one half of its point list and directions from one half of each 2D domain, and
// A − B holds the integrand's difference between those halves besides the noise; measured on
// the Cornell box, it reports 6% more than the random split.) With n_A + n_B = n samples and the
// texel's mean m = (n_A·A + n_B·B)/n, the bake keeps per texel
//     D = Σ_s ε_s·(x_s − m) / n = (2·n_A·n_B/n²)·(A − B)        (W/m², per channel)
// (no extra rays; one vec3 a texel). Given the samples D has mean 0 and variance
// Σ(x_s − m)²/n² = s²(n−1)/n², the variance of the texel's mean, and m ± D (A and B exactly
// when n_A = n_B) are two half-sample maps, each with twice the map's variance.
//
// Filters: the fill of unresolved zeros, the dilation and the seam stitch are linear in the map
// with masks that do not depend on its values: D goes through them as the map does, and F(D) is
// a draw of their output's noise. The denoiser is not linear: its weights follow the map's
// luminance (an edge stop at 2 combined standard errors), so a texel that noise pushed away from
// its neighbours keeps more of its own value. Held fixed at the full map's weights and applied
// to D, it smooths D more than it smoothed the map's own noise (measured: the Cornell box's
// reported error 0.67× the measured). So each half map is denoised on its own, as the map is,
// with its own standard error (√2 the map's) in the guide, and the draw is
// (F(m + D) − F(m − D))/2 (Cornell box: 1.07×). Its bias at the true map, F(E) − E (a real
// gradient smoothed), is taken as F(F(m)) − F(m): the weights the map was denoised with, applied
// to the denoised map; for a fixed linear F that is F(F(E) − E) plus F's change to the little
// noise F(m) keeps, the bias as F smooths it.
//
// The adaptive stop is biased low (a skewed texel stops when its mean happens to be low;
// stoppingBias), which the halves cannot see, since both share the stop: the mean of each
// texel's first kMinAdaptiveSpp samples, a fixed count, is unbiased and measures it, pooled
// per chart.
//
// What it leaves out: the fill's bias (an unresolved texel takes its neighbours' mean), and
// the bias of the converged bake the user would compare with (none: fixed count, its own
// denoiser's bias shrinks with its noise).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "image/image.h"

namespace bounce {

struct DenoiseGuide;  // lightmap_filters.h

// +1 (half A) or −1 (half B) for sample `sample` of texel `texel`.
float splitSign(uint32_t seed, uint32_t texel, uint32_t sample);

// Accumulates Σ ε_s·x_s and Σ ε_s over a texel's samples.
struct HalfSplit {
  glm::dvec3 signedSum{0.0};
  double signs = 0.0;
  void add(glm::vec3 sample, float sign) {
    signedSum += static_cast<double>(sign) * glm::dvec3(sample);
    signs += static_cast<double>(sign);
  }
  // D = (Σ ε·x − m·Σ ε)/n for the texel's mean m over n samples (W/m²).
  glm::vec3 difference(glm::dvec3 mean, uint32_t n) const;
};

// Denoises `map` (denoise(), lightmap_filters.h) and sends `draw` through the same weighted
// means; then adds to `draw` the denoiser's bias estimated on the map: F(F(full)) − F(full),
// the same weights applied to the denoised map (the denoiser run again on the noisy map with
// the denoised one alongside). For a fixed linear F the bias at the true map E is F(E) − E, and
// F(F(full)) − F(full) = F(F(E) − E) + F(F(n) − n): the bias as F smooths it, plus the change F
// makes to the little noise its output has left.
void denoiseWithErrorDraw(Image& map, Image& draw, const DenoiseGuide& guide);

// The adaptive stop's bias, relative, per texel: a texel stops when its estimate looks good,
// which for a skewed integrand is when its mean is low, so E[full] < E. The mean P of its first
// kMinAdaptiveSpp samples (a fixed count, always taken) is unbiased, so E[full − P] is the bias;
// one texel's full − P is mostly noise (P's), so it is pooled per chart (`labels`) over the
// `mask`ed texels with E > 0: Σ(lum full − P) / Σ lum full, or over the whole map for a chart of
// fewer than kStopBiasChartTexels such texels. `full` before any filter.
inline constexpr std::size_t kStopBiasChartTexels = 256;
std::vector<float> stoppingBias(const Image& full, const std::vector<float>& prefixLuminance,
                                const std::vector<uint8_t>& mask,
                                const std::vector<uint32_t>& labels);
// draw += bias × map, per texel (the bias relative to the filtered map it shifts).
void addStoppingBias(Image& draw, const Image& map, const std::vector<float>& bias);

// The delivered map's estimated relative error over the texels with mask ≠ 0 and a lit
// delivered value: per texel |lum D_F| / lum E_F (D_F, E_F the filtered draw and map). Where
// `unknown` ≠ 0 the texel's error is not known: the adaptive stop left it at 0 and it took its
// neighbours' mean (fillUnresolvedZeros); it knows only that its own E is small. Measured
// against converged bakes, such texels are 10% off in the sunlit room (mean; a dim room lit
// through a door) and 7× too bright in the Conference Room (luminance-weighted; 0.4 W/m² where
// the converged bake holds 1e-5). Their perTexel is 1 and they are counted apart, not in the
// mean, p95 or luminance-weighted figure.
struct DeliveredError {
  float mean = 0.0f;               // mean over the texels
  float p95 = 0.0f;                // 95th percentile
  float luminanceWeighted = 0.0f;  // Σ |lum D_F| / Σ lum E_F: the error of the light shown
  std::size_t unknownTexels = 0;   // lit texels whose error is not known (above)
  std::vector<float> perTexel;     // per texel, −1 where not estimated, 1 where not known
};
DeliveredError deliveredError(const Image& map, const Image& difference,
                              const std::vector<uint8_t>& mask,
                              const std::vector<uint8_t>& unknown);

}  // namespace bounce
