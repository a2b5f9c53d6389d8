// The rider's window: draws the DisplayNode's state into the layout (status line, map, list,
// prompt with the Go button, the full-height STOP area) and turns the pointer into choices:
// a click, or a pointer resting for the dwell time (the ring fills), on a room opens it, on a
// place chooses it, on Go confirms it (a click on free floor chooses that spot); pressing or
// (stop_on_hover) entering the STOP area stops the chair. The carer's tools open only after holding
// the small Carer button for carer_hold seconds, which neither a dwell nor the switch can do.
#pragma once

#include "display_node.h"

#include <wheelchair_display/dwell.h>
#include <wheelchair_display/layout.h>

#include <QComboBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTimer>
#include <QWidget>

#include <optional>
#include <vector>

namespace wheelchair_display {

class DisplayWindow : public QWidget {
  Q_OBJECT

 public:
  explicit DisplayWindow(DisplayNode& node);

 protected:
  void paintEvent(QPaintEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void leaveEvent(QEvent* event) override;

 private:
  enum class TargetKind { kRoom = 1, kPlace, kSpot, kGo, kBack };
  enum class CarerMode { kClosed, kTools, kSetPose, kSavePlace, kDeletePlace };
  enum class ViewMode { kOverview, kRoom, kDrive };

  void onTick();
  /// What the next frame would show, in short: no repaint while it stays the same.
  std::string frameKey(double now) const;
  /// The dwell id of what is under `p` (kind * 10000 + index), or kNoTarget. A spot of bare
  /// floor is chosen by a click only: a pointer resting on the map to look is not a choice.
  int targetAt(const QPointF& p, bool for_dwell) const;
  void activate(int target, const QPointF& at);
  void stopChair();

  ViewMode viewMode() const;
  const RoomArea* shownRoom() const;
  void paintMap(QPainter& painter, double now);
  void paintStatus(QPainter& painter, const Message& message);
  void paintList(QPainter& painter);
  void paintPrompt(QPainter& painter, const Message& message);
  void paintStop(QPainter& painter);
  /// The rider's switch choice (a room's places scanned, a place to confirm) leads the map and
  /// the pointer's map targets wait; not while the carer's tools are open.
  bool switchLeads() const;
  bool flashOn(double now) const;

  void buildCarerPanel();
  void setCarerMode(CarerMode mode);
  void placeCarerPanel();

  DisplayNode& node_;
  Layout layout_;
  ViewTransform view_;
  QTimer timer_;
  DwellTimer dwell_;
  double dwell_radius_px_ = 1.0;
  DwellTimer::State dwell_state_;
  QPointF pointer_;
  bool pointer_inside_ = false;
  bool in_stop_ = false;
  std::vector<std::pair<QRectF, int>> rect_targets_;  ///< plates and buttons drawn this frame
  QElapsedTimer clock_;
  std::string last_frame_;

  CarerMode carer_ = CarerMode::kClosed;
  bool holding_carer_ = false;
  QElapsedTimer carer_hold_;
  std::optional<QPointF> pose_anchor_;
  QPointF pose_drag_;
  std::string delete_candidate_;
  QWidget* carer_panel_ = nullptr;
  QLabel* carer_note_ = nullptr;
  QLineEdit* name_edit_ = nullptr;
  QComboBox* room_box_ = nullptr;
  std::vector<QPushButton*> tool_buttons_, save_buttons_, delete_buttons_;
  QPushButton* theme_button_ = nullptr;
  QPushButton* orientation_button_ = nullptr;
  QPushButton* speech_button_ = nullptr;
  QPushButton* delete_button_ = nullptr;
};

}  // namespace wheelchair_display
