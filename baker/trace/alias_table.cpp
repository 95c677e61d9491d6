#include "trace/alias_table.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace bounce {

AliasTable::AliasTable(std::span<const double> weights) {
  double total = 0.0;
  for (double w : weights) {
    if (!std::isfinite(w) || w < 0.0) throw std::invalid_argument("alias table: bad weight");
    total += w;
  }
  if (weights.empty() || !(total > 0.0)) throw std::invalid_argument("alias table: no weight");
  const std::size_t n = weights.size();
  pmf_.resize(n);
  threshold_.assign(n, 1.0f);
  alias_.resize(n);
  // Scaled weights p_i = n·w_i/Σw; Vose's method pairs each under-full bin with an over-full one.
  std::vector<double> scaled(n);
  std::vector<uint32_t> small, large;
  for (std::size_t i = 0; i < n; ++i) {
    pmf_[i] = static_cast<float>(weights[i] / total);
    scaled[i] = weights[i] / total * static_cast<double>(n);
    alias_[i] = static_cast<uint32_t>(i);
    (scaled[i] < 1.0 ? small : large).push_back(static_cast<uint32_t>(i));
  }
  while (!small.empty() && !large.empty()) {
    const uint32_t s = small.back();
    small.pop_back();
    const uint32_t l = large.back();
    threshold_[s] = static_cast<float>(scaled[s]);
    alias_[s] = l;
    scaled[l] -= 1.0 - scaled[s];
    if (scaled[l] < 1.0) {
      large.pop_back();
      small.push_back(l);
    }
  }
  // Leftovers are full bins up to rounding.
  for (uint32_t i : small) threshold_[i] = 1.0f;
  for (uint32_t i : large) threshold_[i] = 1.0f;
}

uint32_t AliasTable::sample(glm::vec2 u) const {
  const auto n = static_cast<uint32_t>(pmf_.size());
  const uint32_t bin = std::min(static_cast<uint32_t>(u.x * static_cast<float>(n)), n - 1);
  return u.y < threshold_[bin] ? bin : alias_[bin];
}

}  // namespace bounce
