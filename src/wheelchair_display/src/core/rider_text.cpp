#include <wheelchair_display/rider_text.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <regex>

namespace wheelchair_display {
namespace {

using Phase = DriveView::Phase;
using Tone = Message::Tone;
using Scan = ScanView::State;
using Loc = LocalizationView::State;

/// The destination as words: the place's name, or "the chosen spot" for a point on the map.
std::string destinationName(const std::string& id) {
  return id.empty() ? "the chosen spot" : riderName(id);
}

/// `text` with its first letter capital (a sentence that begins with a name or "the").
std::string sentence(std::string text) {
  if (!text.empty()) text[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(text[0])));
  return text;
}

/// Another node's words (the supervisor's, the localizer's, the navigator's) as a sentence:
/// capital first letter, a full stop at the end; `fallback` when there are none.
std::string orDefault(const std::string& given, const std::string& fallback) {
  if (given.empty()) return fallback;
  std::string text = sentence(given);
  if (text.back() != '.' && text.back() != '!' && text.back() != '?') text += '.';
  return text;
}

/// The scanning HMI's prompt (what a switch press does now), or "".
std::string scanPrompt(const ScanView& scan) {
  const std::string item = scan.highlightedItem();
  switch (scan.state) {
    case Scan::kRooms:
    case Scan::kPlaces:
      return item.empty() ? "" : "Press to choose " + riderName(item) + ".";
    case Scan::kConfirming:
      return "Press again to go to " + destinationName(scan.place) + ".";
    case Scan::kDriving:
      return "Press to stop.";
    case Scan::kIdle:
      break;
  }
  return "";
}

/// The drive's status sentence and tone; false if there is no drive to speak of.
bool driveStatus(const DriveView& drive, Message& m) {
  const std::string where = destinationName(drive.destination);
  switch (drive.phase) {
    case Phase::kNone:
      return false;
    case Phase::kChecking:
      m.status = "Checking the way to " + where + ".";
      return true;
    case Phase::kReachable:
      m.status = sentence(std::isfinite(drive.distance)
                              ? where + " is " + distanceText(drive.distance) + " away."
                              : where + " is chosen.");  // no route check available
      m.prompt = "Press Go to drive there.";
      m.show_go = true;
      m.tone = Tone::kAttention;
      return true;
    case Phase::kRefused:
      m.status = orDefault(drive.sentence, "The chair cannot get to " + where + ".");
      m.prompt = "Choose another place.";
      m.tone = Tone::kAttention;
      return true;
    case Phase::kDriving:
      if (!drive.sentence.empty()) {  // held up: the navigator says why
        m.status = orDefault(drive.sentence, "");
        m.prompt = "Press STOP or the switch to stop.";
        m.tone = Tone::kAttention;
        return true;
      }
      m.status = std::isfinite(drive.distance)
                     ? "Driving to " + where + " \u2014 " + distanceText(drive.distance) + " to go."
                     : "Driving to " + where + ".";
      m.prompt = "Press STOP or the switch to stop.";
      return true;
    case Phase::kArrived:
      m.status = orDefault(drive.sentence, "Arrived at " + where + ".");
      return true;
    case Phase::kStoppedByRider:
      m.status = orDefault(drive.sentence, "Stopped: you pressed stop.");
      m.tone = Tone::kStopped;
      return true;
    case Phase::kFailed:
      m.status = orDefault(drive.sentence, "Stopped on the way to " + where + ".");
      m.tone = Tone::kStopped;
      return true;
  }
  return false;
}

}  // namespace

std::string riderName(const std::string& id) {
  std::string words;
  for (char c : id) words += (c == '_' || c == '-') ? ' ' : c;
  if (!words.empty())
    words[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(words[0])));
  return words;
}

std::string hmiWords(const std::string& sentence) {
  std::string words = sentence;
  std::replace_if(
      words.begin(), words.end(), [](char c) { return c == '_'; }, ' ');
  return words;
}

std::string distanceText(double metres) {
  char text[32];
  if (metres < 9.95)
    std::snprintf(text, sizeof(text), "%.1f m", std::max(0.0, metres));
  else
    std::snprintf(text, sizeof(text), "%.0f m", metres);
  return text;
}

Message describe(const DisplayInputs& in) {
  Message m;
  const std::string scan_prompt = scanPrompt(in.scan);
  if (!in.have_map) {
    m.status = "Waiting for the map.";
    return m;
  }
  // The supervisor's and the localizer's own sentences; ours only when they give none.
  if (in.safety.known && in.safety.stop) {
    m.status = orDefault(in.safety.sentence, "Stopped.");
    m.tone = Message::Tone::kStopped;
    m.prompt = scan_prompt.empty() ? "Choose where to go to drive on." : scan_prompt;
    return m;
  }
  const bool lost = in.localization.state == Loc::kNotLocalized;
  if (lost || !in.have_pose) {
    m.status = lost ? orDefault(in.localization.sentence, "I am not sure where the chair is.")
                    : "I don't know where the chair is yet.";
    m.tone = Message::Tone::kAttention;
    m.prompt = "A carer can set the chair's position.";
    return m;
  }
  if (driveStatus(in.drive, m)) {
    // A scanning HMI owns the switch: its prompt says what a press does.
    if (!scan_prompt.empty() && !m.show_go) m.prompt = scan_prompt;
    if (m.prompt.empty())
      m.prompt = in.scan.scanning() ? scan_prompt : "Point at a room to choose it.";
    return m;
  }
  if (in.scan.state == Scan::kDriving) {
    // A drive only the HMI told of: in its own words (the navigator's, as it relays them).
    m.status =
        orDefault(hmiWords(in.scan.sentence), "Driving to " + destinationName(in.scan.place) + ".");
    m.prompt = scan_prompt;
    return m;
  }
  m.status = "Choose where to go.";
  m.prompt = !scan_prompt.empty()      ? scan_prompt
             : in.pointer_room.empty() ? "Point at a room to choose it."
                                       : "Point at a place to choose it.";
  return m;
}

std::string spokenText(const std::string& sentence) {
  std::string text = std::regex_replace(sentence, std::regex(" \u2014 "), ", ");
  return std::regex_replace(text, std::regex("([0-9]) m\\b"), "$1 metres");
}

}  // namespace wheelchair_display
