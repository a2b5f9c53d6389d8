// Tests and benchmarks: config/sim.yaml of this source tree (the nodelet finds it at run time).
#pragma once

#include <string>

namespace wheelchair_sim::test {

std::string simConfigFile();

}  // namespace wheelchair_sim::test
