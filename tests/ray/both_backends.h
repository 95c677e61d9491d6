// Runs a parameterised ray-kernel test once per backend, named after it:
//   INSTANTIATE_TEST_SUITE_P(Backends, SomeTest, kBothBackends, backendName);
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "ray/ray_kernel.h"

namespace bounce {

inline const auto kBothBackends = ::testing::Values(RayBackend::Embree, RayBackend::Bvh);

inline std::string backendName(const ::testing::TestParamInfo<RayBackend>& backend) {
  return backend.param == RayBackend::Embree ? "Embree" : "Bvh";
}

}  // namespace bounce
