// The value of one of a model's output channels (io::model_channels) at a state, for
// tests; a missing channel is a test failure (and 0).
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "seaflex/io/model_loader.hpp"

namespace seaflex::testing {

inline double channel(const io::Model& m, const State& s, const std::string& name) {
  for (const Channel& c : io::model_channels(m))
    if (c.name == name) return c.value(s);
  ADD_FAILURE() << "no channel " << name;
  return 0.0;
}

}  // namespace seaflex::testing
