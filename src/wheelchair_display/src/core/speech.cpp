#include <wheelchair_display/rider_text.h>
#include <wheelchair_display/speech.h>

#include <sstream>

namespace wheelchair_display {

std::vector<std::string> espeakArguments(const SpeechSettings& settings,
                                         const std::string& wav_path) {
  std::vector<std::string> args = {"-v",     settings.voice,
                                   "-a",     std::to_string(settings.volume),
                                   "-s",     std::to_string(settings.rate),
                                   "--stdin"};
  if (!wav_path.empty()) args.insert(args.end(), {"-w", wav_path});
  return args;
}

double expectedSpeechSeconds(const std::string& text, int rate) {
  std::istringstream words(text);
  int count = 0;
  for (std::string w; words >> w;) ++count;
  return count * 60.0 / rate;
}

std::string Announcer::onStatus(const std::string& status) {
  if (status == last_status_) return "";
  last_status_ = status;
  return status;
}

std::string Announcer::onScan(const ScanView& scan) {
  std::string say;
  if (scan.state == ScanView::State::kRooms || scan.state == ScanView::State::kPlaces)
    say = scan.highlightedItem().empty() ? "" : riderName(scan.highlightedItem()) + "?";
  else if (scan.state == ScanView::State::kConfirming)
    say = "Go to " + riderName(scan.place) + "?";
  // Said once per change of what is highlighted.
  const std::string key = say + "#" + std::to_string(static_cast<int>(scan.state)) + "#" +
                          std::to_string(scan.highlighted) + "#" + scan.room;
  if (!speak_highlight_ || say.empty() || key == last_scan_) {
    if (say.empty()) last_scan_.clear();
    return "";
  }
  last_scan_ = key;
  return say;
}

}  // namespace wheelchair_display
