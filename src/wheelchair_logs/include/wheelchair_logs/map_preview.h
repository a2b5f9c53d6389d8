// A PNG picture of an MRPT occupancy grid (white free, black occupied, grey unknown; north up).
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <string>

namespace wheelchair_logs {

/// Grey level 255 * P(free) per cell, black where P(occupied) > 0.5; throws std::runtime_error if
/// the file cannot be written.
void savePreviewPng(const mrpt::maps::COccupancyGridMap2D& grid, const std::string& png_path);

}  // namespace wheelchair_logs
