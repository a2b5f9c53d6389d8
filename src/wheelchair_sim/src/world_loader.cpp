#include <wheelchair_core/map_io.h>
#include <wheelchair_mapping/mrpt_conversions.h>
#include <wheelchair_sim/world_loader.h>

namespace wheelchair_sim {

std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> loadWorld(const std::string& yaml_path) {
  return std::make_shared<const mrpt::maps::COccupancyGridMap2D>(
      wheelchair_mapping::toMrptGrid(wheelchair_core::loadMap(yaml_path)));
}

}  // namespace wheelchair_sim
