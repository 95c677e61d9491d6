// The summary bake.json gives of per-texel relative errors (before the filters, and of the
// delivered map: delivered_error.h): their mean and their 95th percentile, the value at rank
// ⌊0.95·n⌋ of the sorted list (the last one for n < 20). GL-free, header only.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace bounce {

struct ErrorSummary {
  float mean = 0.0f, p95 = 0.0f;  // relative, 0 when there is no error to summarise
};

// `errors` by value: the percentile reorders it.
inline ErrorSummary summariseErrors(std::vector<float> errors) {
  ErrorSummary s;
  if (errors.empty()) return s;
  double sum = 0.0;
  for (const float e : errors) sum += e;
  s.mean = static_cast<float>(sum / static_cast<double>(errors.size()));
  const std::size_t k = std::min(errors.size() - 1, errors.size() * 95 / 100);
  std::nth_element(errors.begin(), errors.begin() + static_cast<std::ptrdiff_t>(k), errors.end());
  s.p95 = errors[k];
  return s;
}

}  // namespace bounce
