// The sampler's uniformity: exact stratification per elementary interval, faster-than-MC
// convergence on a smooth integrand, independence of dimension pairs, determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "trace/alias_table.h"
#include "trace/rng.h"
#include "trace/sobol_sampler.h"

namespace bounce {
namespace {

TEST(SobolSampler, FirstTwoDimensionsAreTheSobolSequence) {
  // Sobol dimension 1 in index (not Gray-code) order: x_i = XOR of the direction numbers
  // 0.1b, 0.11b, 0.101b for the set bits of i.
  const double expected[] = {0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875};
  for (uint32_t i = 0; i < 8; ++i) {
    EXPECT_EQ(sobolDimension1(i) * 0x1p-32, expected[i]) << i;
    EXPECT_EQ(sobolDimension0(i) * 0x1p-32, reverseBits(i) * 0x1p-32);
  }
}

TEST(SobolSampler, NestedScrambleIsABijectionThatKeepsPrefixes) {
  // Owen scrambling maps each dyadic interval of length 2^-k onto another one: the top k
  // bits of the output depend only on the top k bits of the input.
  const uint32_t seed = 0x1234567u;
  for (uint32_t k = 1; k <= 12; ++k) {
    const uint32_t shift = 32 - k;
    for (uint32_t prefix = 0; prefix < (1u << k); prefix += 1 + (prefix >> 3)) {
      const uint32_t a = nestedUniformScramble(prefix << shift, seed) >> shift;
      const uint32_t b = nestedUniformScramble((prefix << shift) | 0x5a5a5u, seed) >> shift;
      EXPECT_EQ(a, b) << "k " << k << " prefix " << prefix;
    }
  }
  std::vector<uint8_t> seen(1u << 16, 0);
  for (uint32_t x = 0; x < (1u << 16); ++x) seen[nestedUniformScramble(x << 16, seed) >> 16] = 1;
  for (uint8_t s : seen) ASSERT_EQ(s, 1);
}

// For every m ≤ 10 and every split i + j = m, the first 2^m points of a pair put exactly one
// point into each elementary interval of size 2^-i × 2^-j: a (0,m,2)-net, which implies a
// star discrepancy of O(log N / N).
TEST(SobolSampler, EveryPowerOfTwoPrefixIsA02Net) {
  for (uint32_t pixel : {0u, 7u, 123456u}) {
    for (uint32_t dimension : {0u, 1u, 5u, 17u}) {
      SobolSampler sampler(42u, pixel);
      std::vector<glm::vec2> points;
      for (uint32_t i = 0; i < 1024; ++i) {
        sampler.startSample(i);
        sampler.setDimension(dimension);
        points.push_back(sampler.get2D());
      }
      for (uint32_t m = 0; m <= 10; ++m) {
        const uint32_t n = 1u << m;
        for (uint32_t i = 0; i <= m; ++i) {
          const uint32_t j = m - i;
          std::vector<int> count(n, 0);
          for (uint32_t s = 0; s < n; ++s) {
            const auto cx = static_cast<uint32_t>(points[s].x * static_cast<float>(1u << i));
            const auto cy = static_cast<uint32_t>(points[s].y * static_cast<float>(1u << j));
            ++count[(cy << i) | cx];
          }
          for (int c : count) {
            ASSERT_EQ(c, 1) << "pixel " << pixel << " dim " << dimension << " m " << m << " split "
                            << i << "x" << j;
          }
        }
      }
    }
  }
}

// f(x,y) = e^x sin(πy) on [0,1)², ∫f = (e − 1)·2/π. Plain Monte Carlo has RMSE ∝ N^(−1/2):
// going from 16 to 1024 samples (64×) divides it by 8. Owen-scrambled nets on a smooth
// integrand give N^(−3/2), a factor 512. Requiring a factor > 32 (rate faster than N^(−0.83))
// separates the two by far more than the ~10% error of an RMSE measured over 64 patterns.
TEST(SobolSampler, SmoothIntegrandConvergesFasterThanMonteCarlo) {
  const double exact = (std::exp(1.0) - 1.0) * 2.0 / M_PI;
  auto rmse = [&](uint32_t n) {
    double sum2 = 0.0;
    for (uint32_t pattern = 0; pattern < 64; ++pattern) {
      SobolSampler sampler(9u, pattern);
      double sum = 0.0;
      for (uint32_t i = 0; i < n; ++i) {
        sampler.startSample(i);
        sampler.setDimension(3);
        const glm::vec2 u = sampler.get2D();
        sum += std::exp(static_cast<double>(u.x)) * std::sin(M_PI * static_cast<double>(u.y));
      }
      const double error = sum / n - exact;
      sum2 += error * error;
    }
    return std::sqrt(sum2 / 64.0);
  };
  const double coarse = rmse(16);
  const double fine = rmse(1024);
  std::printf("RMSE 16 samples %.3g, 1024 samples %.3g, ratio %.1f (MC: 8, ideal: 512)\n", coarse,
              fine, coarse / fine);
  EXPECT_GT(coarse / fine, 32.0);
}

// Distinct pairs must be independent: E[x_a·x_b] = 1/4 and E[x] = 1/2. With N = 4096 and
// Var(x_a·x_b) = 7/144, 5 standard errors are 5·sqrt(7/144/4096) ≈ 0.0172 (a conservative
// bound: the scrambled nets are more accurate than independent samples).
TEST(SobolSampler, DimensionPairsAreUncorrelated) {
  const int n = 4096;
  for (uint32_t a = 0; a < 6; ++a) {
    double product = 0.0, mean = 0.0;
    SobolSampler sampler(3u, 11u);
    for (int i = 0; i < n; ++i) {
      sampler.startSample(static_cast<uint32_t>(i));
      sampler.setDimension(a);
      const float x = sampler.get1D();
      sampler.setDimension(a + 1);
      const float y = sampler.get1D();
      product += static_cast<double>(x) * y;
      mean += x;
    }
    EXPECT_NEAR(product / n, 0.25, 5.0 * std::sqrt(7.0 / 144.0 / n)) << "pair " << a;
    EXPECT_NEAR(mean / n, 0.5, 5.0 * std::sqrt(1.0 / 12.0 / n));
  }
}

TEST(SobolSampler, ValuesDependOnlyOnSeedPixelIndexAndDimension) {
  SobolSampler a(5u, 77u), b(5u, 77u), c(6u, 77u);
  a.startSample(1000);
  a.setDimension(9);
  const glm::vec2 first = a.get2D();
  // b visits other samples and dimensions first; the same keys give the same value.
  for (uint32_t i = 0; i < 10; ++i) {
    b.startSample(i);
    b.get2D();
  }
  b.startSample(1000);
  b.setDimension(9);
  EXPECT_EQ(first, b.get2D());
  c.startSample(1000);
  c.setDimension(9);
  EXPECT_NE(first, c.get2D());
  for (uint32_t i = 0; i < 4096; ++i) {
    a.startSample(i);
    const glm::vec2 u = a.get2D();
    ASSERT_TRUE(u.x >= 0.0f && u.x < 1.0f && u.y >= 0.0f && u.y < 1.0f);
  }
}

// Frequencies of 10^5 draws follow the weights: each count is binomial, 5 standard
// deviations sqrt(N p (1−p)) allowed.
TEST(AliasTable, SamplesFollowTheWeights) {
  const std::vector<double> weights = {1.0, 0.0, 3.0, 0.5, 10.0, 0.25};
  const AliasTable table(weights);
  double total = 0.0;
  for (double w : weights) total += w;
  const int n = 100000;
  std::vector<int> count(weights.size(), 0);
  for (int i = 0; i < n; ++i) {
    ++count[table.sample({uniformFloat(1u, static_cast<uint32_t>(2 * i)),
                          uniformFloat(1u, static_cast<uint32_t>(2 * i + 1))})];
  }
  for (std::size_t i = 0; i < weights.size(); ++i) {
    const double p = weights[i] / total;
    EXPECT_NEAR(table.pmf(static_cast<uint32_t>(i)), p, 1e-6);
    EXPECT_NEAR(count[i], n * p, 5.0 * std::sqrt(n * p * (1.0 - p)) + 1e-9) << i;
  }
  EXPECT_EQ(count[1], 0);
  EXPECT_THROW(AliasTable(std::vector<double>{0.0, 0.0}), std::invalid_argument);
}

}  // namespace
}  // namespace bounce
