// The ground-truth world: a map_server YAML + image, as an MRPT grid.
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <memory>
#include <string>

namespace wheelchair_sim {

/// Loads `yaml_path` with wheelchair_core::loadMap and converts it with toMrptGrid.
/// Throws wheelchair_core::MapFileError / std::invalid_argument naming the problem.
std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> loadWorld(const std::string& yaml_path);

}  // namespace wheelchair_sim
