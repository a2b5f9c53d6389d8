// The display's settings (the one parameter pattern, wheelchair_core/config.h): defaults here
// only, validate() says what is wrong, readDisplayConfig() names every key, so the node and an
// offline tool read the same keys.
#pragma once

#include <wheelchair_core/config.h>
#include <wheelchair_display/speech.h>

#include <string>

namespace wheelchair_display {

struct DisplayConfig {
  std::string theme = "dark";            ///< dark | light
  std::string orientation = "north_up";  ///< north_up | chair_up
  double dwell_time = 1.5;               ///< [s] a pointer resting this long chooses
  double dwell_radius = 0.05;            ///< pointer jitter allowed while dwelling [screen heights]
  bool stop_on_hover = true;             ///< the pointer entering the STOP area stops the chair
  double outcome_hold = 30.0;            ///< [s] a drive's outcome stays on the status line
  double min_view_extent = 4.0;          ///< [m] the view never zooms in closer than this across
  double room_pad = 0.6;                 ///< [m] a room's area around its places
  double carer_hold = 3.0;               ///< [s] press and hold to open the carer's tools
  double flash_period = 1.0;  ///< [s] the highlight's edge flashes (<= 3 per s: WCAG 2.3.1)
  SpeechSettings speech;
  bool speak_highlight = false;  ///< auditory scanning: say each highlighted room / place

  std::string validate() const;
};

/// Keys: theme, orientation, dwell_time, dwell_radius, stop_on_hover, outcome_hold,
/// min_view_extent, room_pad, carer_hold, flash_period, speech, speech_voice, speech_volume,
/// speech_rate, speak_highlight.
void readDisplayConfig(wheelchair_core::ConfigReader& reader, DisplayConfig& config);

}  // namespace wheelchair_display
