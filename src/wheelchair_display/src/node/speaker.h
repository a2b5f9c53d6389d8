// Says announcements with espeak-ng (a QProcess; a new announcement cuts the one still being
// said, so "Stopped" never waits behind a long sentence), or writes each one to a WAV file.
#pragma once

#include <wheelchair_display/speech.h>

#include <QObject>
#include <QProcess>

#include <string>

namespace wheelchair_display {

class Speaker : public QObject {
  Q_OBJECT

 public:
  /// With `wav_dir` set, announcement N is written to wav_dir/NNN.wav and its text to NNN.txt.
  Speaker(SpeechSettings settings, std::string wav_dir, QObject* parent = nullptr);
  ~Speaker() override;
  void say(const std::string& text);
  void setSettings(const SpeechSettings& settings) { settings_ = settings; }
  const SpeechSettings& settings() const { return settings_; }

 private:
  SpeechSettings settings_;
  std::string wav_dir_;
  QProcess* process_ = nullptr;
  int count_ = 0;
  bool warned_ = false;
};

}  // namespace wheelchair_display
