#include <wheelchair_display/display_config.h>
#include <wheelchair_display/map_view.h>
#include <wheelchair_display/theme.h>

#include <stdexcept>

namespace wheelchair_display {
namespace {

bool named(const std::string& value, Orientation (*parse)(const std::string&)) {
  try {
    parse(value);
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

bool themeKnown(const std::string& name) {
  try {
    themeNamed(name);
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

}  // namespace

std::string DisplayConfig::validate() const {
  wheelchair_core::ConfigChecks checks;
  checks.check(themeKnown(theme), "theme '" + theme + "' is not dark or light")
      .check(named(orientation, orientationNamed),
             "orientation '" + orientation + "' is not north_up or chair_up")
      .inRange("dwell_time", dwell_time, 0.3, 10.0)
      .inRange("dwell_radius", dwell_radius, 0.005, 0.5)
      .positive("outcome_hold", outcome_hold)
      .inRange("min_view_extent", min_view_extent, 0.5, 100.0)
      .nonNegative("room_pad", room_pad)
      .inRange("carer_hold", carer_hold, 1.0, 30.0)
      .inRange("flash_period", flash_period, 0.67, 5.0)
      .check(!speech.voice.empty(), "speech_voice is empty")
      .inRange("speech_volume", speech.volume, 0, 200)
      .inRange("speech_rate", speech.rate, 80, 450);
  return checks.result();
}

void readDisplayConfig(wheelchair_core::ConfigReader& reader, DisplayConfig& config) {
  reader.read("theme", config.theme);
  reader.read("orientation", config.orientation);
  reader.read("dwell_time", config.dwell_time);
  reader.read("dwell_radius", config.dwell_radius);
  reader.read("stop_on_hover", config.stop_on_hover);
  reader.read("outcome_hold", config.outcome_hold);
  reader.read("min_view_extent", config.min_view_extent);
  reader.read("room_pad", config.room_pad);
  reader.read("carer_hold", config.carer_hold);
  reader.read("flash_period", config.flash_period);
  reader.read("speech", config.speech.enabled);
  reader.read("speech_voice", config.speech.voice);
  reader.read("speech_volume", config.speech.volume);
  reader.read("speech_rate", config.speech.rate);
  reader.read("speak_highlight", config.speak_highlight);
}

}  // namespace wheelchair_display
