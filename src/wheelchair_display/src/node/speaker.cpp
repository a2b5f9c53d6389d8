#include "speaker.h"

#include <ros/console.h>

#include <QStringList>

#include <cstdio>
#include <fstream>

namespace wheelchair_display {

Speaker::Speaker(SpeechSettings settings, std::string wav_dir, QObject* parent)
    : QObject(parent), settings_(std::move(settings)), wav_dir_(std::move(wav_dir)) {}

Speaker::~Speaker() {
  if (process_ && process_->state() != QProcess::NotRunning) {
    process_->kill();
    process_->waitForFinished(500);
  }
}

void Speaker::say(const std::string& text) {
  if (!settings_.enabled || text.empty()) return;
  std::string wav;
  if (!wav_dir_.empty()) {
    char name[32];
    std::snprintf(name, sizeof(name), "/%03d", count_++);
    wav = wav_dir_ + name + ".wav";
    std::ofstream(wav_dir_ + name + ".txt") << text << "\n";
  }
  // A new announcement cuts the one being spoken; files are all kept whole.
  if (process_ && process_->state() != QProcess::NotRunning) {
    if (wav.empty()) process_->kill();
    process_->waitForFinished(wav.empty() ? 500 : 5000);
  }
  if (process_) process_->deleteLater();
  process_ = new QProcess(this);
  QStringList args;
  for (const auto& a : espeakArguments(settings_, wav)) args << QString::fromStdString(a);
  process_->start("espeak-ng", args);
  if (!process_->waitForStarted(2000)) {
    if (!warned_) ROS_ERROR("display: cannot run espeak-ng: announcements are not spoken");
    warned_ = true;
    return;
  }
  process_->write(QByteArray::fromStdString(text + "\n"));
  process_->closeWriteChannel();
}

}  // namespace wheelchair_display
