// Walker/Vose alias table: O(1) sampling of an index i with probability w_i / Σw.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace bounce {

class AliasTable {
 public:
  AliasTable() = default;
  // Weights must be finite and ≥ 0; zero weights are never sampled. Throws
  // std::invalid_argument when the weights are empty, all zero, or not finite.
  explicit AliasTable(std::span<const double> weights);

  std::size_t size() const { return pmf_.size(); }
  bool empty() const { return pmf_.empty(); }
  // u.x picks a bin, u.y tosses its coin; both uniform in [0,1).
  uint32_t sample(glm::vec2 u) const;
  float pmf(uint32_t index) const { return pmf_[index]; }

 private:
  std::vector<float> pmf_;
  std::vector<float> threshold_;  // probability of keeping bin i rather than its alias
  std::vector<uint32_t> alias_;
};

}  // namespace bounce
