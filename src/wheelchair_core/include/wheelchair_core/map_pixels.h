// How map_server turns an image pixel into an occupancy value, and the inverse used when
// saving (map_saver's convention).
#pragma once

#include <wheelchair_core/map_io.h>

#include <cstdint>

namespace wheelchair_core {

/// map_saver's grey for an unknown cell in trinary mode (0 occupied, 254 free).
constexpr uint8_t kTrinaryUnknownPixel = 205;

/// The value map_server's image_loader gives a pixel whose channel average is `color_avg`
/// (0..255) and whose alpha is `alpha` (0..255; 255 when the image has no alpha channel):
/// p = (255 - v) / 255 (v = 255 - color_avg when negated); occupied if p > occupied_thresh,
/// free if p < free_thresh, else unknown (trinary) or 1 + 98 (p - free) / (occ - free) (scale);
/// raw mode stores v itself. In trinary mode v = 205 (map_saver's unknown) is unknown whatever
/// the thresholds (a free_thresh above 0.196 would otherwise read it as free).
int8_t pixelToCell(double color_avg, double alpha, const MapFileOptions& options);

/// The grey value written for `cell` (map_saver: 0 occupied, 254 free, 205 unknown in
/// trinary mode; 255 - 2.55 p in scale mode; the value itself in raw mode), negated if asked.
uint8_t cellToPixel(int8_t cell, const MapFileOptions& options);

}  // namespace wheelchair_core
