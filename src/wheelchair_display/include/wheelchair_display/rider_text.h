// Every word the rider reads or hears: short sentences, place names as words, no frame names or
// coordinates. One status sentence says what the chair is doing and why; one prompt says what
// the next action does ("Press to choose Kitchen.").
#pragma once

#include <wheelchair_display/display_model.h>

#include <string>

namespace wheelchair_display {

/// A places-file identifier as words, first letter capital: "kitchen_door" -> "Kitchen door".
std::string riderName(const std::string& id);
/// The HMI's words (HmiState.sentence) for the screen: the places it names by identifier as
/// words ("Going to kitchen_door." -> "Going to kitchen door.").
std::string hmiWords(const std::string& sentence);
/// "3.2 m" below 10 m, "12 m" from there.
std::string distanceText(double metres);

struct Message {
  enum class Tone { kInfo, kAttention, kStopped };
  std::string status;  ///< what the chair is doing and why
  std::string prompt;  ///< what the next action does
  Tone tone = Tone::kInfo;
  bool show_go = false;  ///< the Go button confirms the chosen destination
};

/// The status sentence and the prompt for what the display knows. Priority: a safety stop, then
/// not knowing where the chair is, then the drive (its outcome, progress, or the check of a
/// choice), then what to choose.
Message describe(const DisplayInputs& in);

/// `sentence` as espeak-ng should say it: "m" spoken as "metres", a dash as a pause.
std::string spokenText(const std::string& sentence);

}  // namespace wheelchair_display
