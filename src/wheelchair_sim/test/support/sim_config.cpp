#include <wheelchair_sim_testing/sim_config.h>

namespace wheelchair_sim::test {

std::string simConfigFile() { return WHEELCHAIR_SIM_CONFIG_FILE; }

}  // namespace wheelchair_sim::test
