// Spoken announcements with espeak-ng: its command line for the rider's settings, how long a
// sentence should take, and what to say when (every new status sentence; with auditory scanning
// also each highlighted item, for riders who cannot watch the screen).
#pragma once

#include <wheelchair_display/display_model.h>

#include <string>
#include <vector>

namespace wheelchair_display {

struct SpeechSettings {
  bool enabled = true;
  std::string voice = "en";  ///< an espeak-ng voice (espeak-ng --voices): en, en-gb, de, fr...
  int volume = 100;          ///< espeak-ng amplitude 0..200
  int rate = 150;            ///< [words per minute] 80..450 (espeak-ng's default is 175)
};

/// espeak-ng's arguments (without the program name) to say the text given on standard input;
/// with `wav_path` it writes a WAV file there instead of playing it.
std::vector<std::string> espeakArguments(const SpeechSettings& settings,
                                         const std::string& wav_path = "");

/// [s] about how long `text` takes at `rate` words per minute (words x 60 / rate).
double expectedSpeechSeconds(const std::string& text, int rate);

/// Decides what to say: a new status sentence, and (auditory scanning) the newly highlighted
/// item or the choice to confirm. Returns "" when nothing new is to be said.
class Announcer {
 public:
  explicit Announcer(bool speak_highlight) : speak_highlight_(speak_highlight) {}
  std::string onStatus(const std::string& status);
  std::string onScan(const ScanView& scan);
  void setSpeakHighlight(bool on) { speak_highlight_ = on; }

 private:
  bool speak_highlight_;
  std::string last_status_;
  std::string last_scan_;
};

}  // namespace wheelchair_display
