#include "display_window.h"

#include "map_painter.h"

#include <wheelchair_display/rider_text.h>

#include <QMouseEvent>
#include <QPainter>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace wheelchair_display {
namespace {

constexpr int kIdScale = 10000;

QString qs(const std::string& s) { return QString::fromStdString(s); }

QPointF qpoint(const Eigen::Vector2d& p) { return {p.x(), p.y()}; }

/// A regular polygon: an octagon (the stop sign's shape) or a triangle (attention).
QPolygonF signShape(const QPointF& centre, double radius, int corners, double turn) {
  QPolygonF shape;
  for (int i = 0; i < corners; ++i) {
    const double a = turn + 2.0 * M_PI * i / corners;
    shape << centre + QPointF(radius * std::cos(a), -radius * std::sin(a));
  }
  return shape;
}

/// Text in `rect`, wrapped, at the largest size from `px` down to `min_px` that fits.
void drawFittedText(QPainter& painter, const QRectF& rect, const QString& text, int px, int min_px,
                    bool bold, int flags) {
  for (; px > min_px; px -= 2) {
    const QFontMetricsF metrics(riderFont(px, bold));
    if (metrics.boundingRect(rect, flags | Qt::TextWordWrap, text).height() <= rect.height()) break;
  }
  painter.setFont(riderFont(px, bold));
  painter.drawText(rect, flags | Qt::TextWordWrap, text);
}

}  // namespace

DisplayWindow::DisplayWindow(DisplayNode& node)
    : node_(node), dwell_(node.config().display.dwell_time, 1.0) {
  setMouseTracking(true);
  setWindowTitle("Wheelchair");
  clock_.start();
  buildCarerPanel();
  connect(&timer_, &QTimer::timeout, this, &DisplayWindow::onTick);
  timer_.start(50);
}

// ---- the tick: ROS, dwell, redraw -----------------------------------------------------------

void DisplayWindow::onTick() {
  node_.tick();
  if (!ros::ok()) {
    close();
    return;
  }
  if (holding_carer_ && carer_hold_.elapsed() >= node_.config().display.carer_hold * 1000.0) {
    holding_carer_ = false;
    setCarerMode(CarerMode::kTools);
  }
  // The dwell radius is a share of the screen height: the same head movement on any screen.
  const double radius = node_.config().display.dwell_radius * height();
  if (std::abs(radius - dwell_radius_px_) > 0.5) {
    dwell_ = DwellTimer(node_.config().display.dwell_time, radius);
    dwell_radius_px_ = radius;
  }
  const double now = clock_.elapsed() / 1000.0;
  if (pointer_inside_ && carer_ != CarerMode::kSetPose) {
    dwell_state_ =
        dwell_.update(now, Eigen::Vector2d(pointer_.x(), pointer_.y()), targetAt(pointer_, true));
    if (dwell_state_.fired) activate(dwell_state_.target, pointer_);
  } else {
    dwell_state_ = DwellTimer::State();
  }
  // Software rendering on an old chair PC: repaint only when something visible changed.
  std::string frame = frameKey(now);
  if (frame != last_frame_ || dwell_state_.progress > 0.0 || holding_carer_ || pose_anchor_)
    update();
  last_frame_ = std::move(frame);
}

std::string DisplayWindow::frameKey(double now) const {
  const Message m = node_.message();
  const ScanView scan = node_.scan();
  const auto& pose = node_.chairPose();
  const auto& drive = node_.drive();
  char numbers[160];
  std::snprintf(numbers, sizeof(numbers), "%d|%d|%d|%.0f|%.2f|%.2f|%.2f|%d|%zu|%zu|%d|%d|%lld|%lld",
                static_cast<int>(scan.state), scan.highlighted, static_cast<int>(scan.items.size()),
                10 * scan.time_left, pose ? pose->x : -1e9, pose ? pose->y : -1e9,
                pose ? pose->yaw : 0.0, static_cast<int>(drive.view().phase),
                drive.routePoses().size(), node_.places().size(), flashOn(now),
                static_cast<int>(carer_), node_.mapImage().cacheKey(),
                node_.obstacleImage().cacheKey());
  return m.status + "|" + m.prompt + "|" + scan.room + "|" + scan.place + "|" +
         node_.pointerRoom() + "|" + node_.theme().name + "|" +
         std::to_string(static_cast<int>(node_.orientation())) + "|" + numbers;
}

// ---- pointer --------------------------------------------------------------------------------

int DisplayWindow::targetAt(const QPointF& p, bool for_dwell) const {
  if (carer_panel_->isVisible() && carer_panel_->geometry().contains(p.toPoint())) return kNoTarget;
  for (const auto& [rect, id] : rect_targets_)
    if (rect.contains(p)) return id;
  if (!layout_.map.contains(p.x(), p.y())) return kNoTarget;
  const ViewMode mode = viewMode();
  const Eigen::Vector2d world = view_.toWorld({p.x(), p.y()});
  if (mode == ViewMode::kOverview) {
    const int room = roomAt(node_.rooms(), world);
    return room >= 0 ? static_cast<int>(TargetKind::kRoom) * kIdScale + room : kNoTarget;
  }
  if (mode == ViewMode::kRoom && !switchLeads() && !for_dwell)
    return static_cast<int>(TargetKind::kSpot) * kIdScale;
  return kNoTarget;
}

void DisplayWindow::activate(int target, const QPointF& at) {
  if (target == kNoTarget) return;
  const auto kind = static_cast<TargetKind>(target / kIdScale);
  const int index = target % kIdScale;
  if (carer_ == CarerMode::kDeletePlace) {
    if (kind == TargetKind::kPlace) {
      delete_candidate_ = node_.places()[index].name;
      delete_button_->setText(qs("Delete " + riderName(delete_candidate_)));
      delete_button_->setEnabled(true);
    }
    if (kind == TargetKind::kRoom) node_.openRoom(node_.rooms()[index].name);
    if (kind == TargetKind::kBack) node_.closeRoom();
    return;
  }
  switch (kind) {
    case TargetKind::kRoom:
      node_.openRoom(node_.rooms()[index].name);
      break;
    case TargetKind::kPlace:
      node_.choosePlace(static_cast<size_t>(index));
      break;
    case TargetKind::kSpot:
      node_.chooseSpot(view_.toWorld({at.x(), at.y()}));
      break;
    case TargetKind::kGo:
      node_.confirm();
      break;
    case TargetKind::kBack:  // "All rooms": the overview, a choice not confirmed withdrawn
      node_.closeRoom();
      node_.withdraw();
      break;
  }
  dwell_.rest(Eigen::Vector2d(at.x(), at.y()));
}

void DisplayWindow::stopChair() { node_.stop(); }

void DisplayWindow::mouseMoveEvent(QMouseEvent* event) {
  pointer_ = event->localPos();
  pointer_inside_ = true;
  const bool in_stop = layout_.stop.contains(pointer_.x(), pointer_.y());
  // Entering the STOP area is the one action a pointer-only rider has: it stops at once.
  if (in_stop && !in_stop_ && node_.config().display.stop_on_hover) stopChair();
  in_stop_ = in_stop;
  if (carer_ == CarerMode::kSetPose && pose_anchor_) pose_drag_ = pointer_;
}

void DisplayWindow::leaveEvent(QEvent*) {
  pointer_inside_ = false;
  in_stop_ = false;
  dwell_.reset();
}

void DisplayWindow::mousePressEvent(QMouseEvent* event) {
  const QPointF p = event->localPos();
  pointer_ = p;
  if (layout_.stop.contains(p.x(), p.y())) {
    stopChair();
    return;
  }
  if (layout_.carer_button.contains(p.x(), p.y()) && carer_ == CarerMode::kClosed) {
    holding_carer_ = true;
    carer_hold_.start();
    return;
  }
  if (carer_ == CarerMode::kSetPose && layout_.map.contains(p.x(), p.y())) {
    pose_anchor_ = p;
    pose_drag_ = p;
    return;
  }
  activate(targetAt(p, false), p);
}

void DisplayWindow::mouseReleaseEvent(QMouseEvent* event) {
  holding_carer_ = false;
  if (carer_ == CarerMode::kSetPose && pose_anchor_) {
    const Eigen::Vector2d at = view_.toWorld({pose_anchor_->x(), pose_anchor_->y()});
    const Eigen::Vector2d to = view_.toWorld({event->localPos().x(), event->localPos().y()});
    const double heading = (to - at).norm() * view_.scale > 10.0
                               ? std::atan2(to.y() - at.y(), to.x() - at.x())
                               : (node_.chairPose() ? node_.chairPose()->yaw : 0.0);
    node_.setPose({at.x(), at.y(), heading});
    pose_anchor_.reset();
    setCarerMode(CarerMode::kTools);
  }
}

// ---- what is shown --------------------------------------------------------------------------

DisplayWindow::ViewMode DisplayWindow::viewMode() const {
  using Phase = DriveView::Phase;
  // The carer puts the chair where it is: the whole map, whatever room the switch opened.
  if (carer_ == CarerMode::kSetPose) return ViewMode::kOverview;
  const Phase phase = node_.drive().view().phase;
  if ((phase == Phase::kChecking || phase == Phase::kReachable || phase == Phase::kDriving) &&
      node_.drive().goalPose())
    return ViewMode::kDrive;
  return shownRoom() ? ViewMode::kRoom : ViewMode::kOverview;
}

const RoomArea* DisplayWindow::shownRoom() const {
  const ScanView scan = node_.scan();
  std::string room = node_.pointerRoom();
  if (switchLeads()) room = scan.room;
  const int index = roomNamed(node_.rooms(), room);
  return index >= 0 ? &node_.rooms()[index] : nullptr;
}

bool DisplayWindow::switchLeads() const {
  // The carer's tools, once open, lead the map (a place to delete, the chair's position).
  return carer_ == CarerMode::kClosed && node_.scan().switchEngaged();
}

bool DisplayWindow::flashOn(double now) const {
  const double period = node_.config().display.flash_period;
  return std::fmod(now, period) < 0.5 * period;
}

void DisplayWindow::paintEvent(QPaintEvent*) {
  const double now = clock_.elapsed() / 1000.0;
  const ScanView scan = node_.scan();
  const bool with_list = scan.scanning() || carer_ != CarerMode::kClosed;
  layout_ = computeLayout(width(), height(), with_list);
  rect_targets_.clear();
  QPainter painter(this);
  painter.setRenderHint(QPainter::Antialiasing, true);
  painter.setRenderHint(QPainter::TextAntialiasing, true);
  painter.fillRect(rect(), qcolor(node_.theme().background));
  const Message message = node_.message();
  paintMap(painter, now);
  paintStatus(painter, message);
  if (layout_.list.w > 0 && carer_ == CarerMode::kClosed) paintList(painter);
  paintPrompt(painter, message);
  paintStop(painter);
  placeCarerPanel();
  drawDwellRing(painter, node_.theme(), pointer_, 0.045 * height(), dwell_state_.progress);
}

void DisplayWindow::paintMap(QPainter& painter, double now) {
  const Theme& theme = node_.theme();
  const Rect& area = layout_.map;
  painter.save();
  painter.setClipRect(area.x, area.y, area.w, area.h);
  painter.fillRect(area.x, area.y, area.w, area.h, qcolor(theme.background));
  const auto& pose = node_.chairPose();
  wheelchair_core::Polygon footprint;
  if (pose) footprint = wheelchair_core::transformPolygon(node_.footprint(), *pose);
  const ViewMode mode = viewMode();
  const RoomArea* room = mode == ViewMode::kRoom ? shownRoom() : nullptr;
  const auto& goal = node_.drive().goalPose();
  const double rotation = viewRotation(node_.orientation(), pose ? pose->yaw : 0.0);
  view_ = fitView(
      area,
      viewFrame(node_.overview(), pose ? &footprint : nullptr, node_.drive().routePoses(),
                mode == ViewMode::kDrive && goal ? &*goal : nullptr, room),
      rotation, (mode == ViewMode::kDrive ? 0.07 : 0.03) * height(),  // room for the goal's sign
      node_.config().display.min_view_extent);
  node_.publishView(view_, area);
  if (const auto* map = node_.map()) drawGrid(painter, view_, *map, node_.mapImage());
  if (const auto* obstacles = node_.obstacles())
    drawGrid(painter, view_, *obstacles, node_.obstacleImage());

  const ScanView scan = node_.scan();
  const bool flash = flashOn(now);
  const auto& places = node_.places();
  const auto& rooms = node_.rooms();
  // What stands out: the HMI's highlighted room or place, or the pointer's choice.
  std::string lit_room, lit_place;
  if (scan.state == ScanView::State::kRooms) lit_room = scan.highlightedItem();
  if (scan.state == ScanView::State::kPlaces) lit_place = scan.highlightedItem();
  if (scan.state == ScanView::State::kConfirming) lit_place = scan.place;
  const auto phase = node_.drive().view().phase;
  if (phase == DriveView::Phase::kChecking || phase == DriveView::Phase::kReachable)
    lit_place = node_.drive().view().destination;

  const double dot = std::max(6.0, 0.009 * height());
  if (mode == ViewMode::kOverview) {
    for (size_t r = 0; r < rooms.size(); ++r) {
      const bool lit = rooms[r].name == lit_room;
      const QPointF a = qpoint(view_.toScreen(rooms[r].box.min));
      const QPointF b = qpoint(view_.toScreen(rooms[r].box.max));
      const QRectF box = QRectF(a, b).normalized();
      painter.setBrush(Qt::NoBrush);
      if (lit) {
        painter.setPen(QPen(qcolor(flash ? theme.highlight_frame : theme.highlight_frame_alt),
                            std::max(8.0, 0.012 * height())));
      } else {
        painter.setPen(QPen(qcolor(theme.label_border), 2.0, Qt::DashLine));
      }
      painter.drawRect(box);
      for (size_t i : rooms[r].places)
        drawPlaceDot(painter, theme, qpoint(view_.toScreen(places[i].pose.position())), dot * 0.7,
                     lit ? Highlight::kGroup : Highlight::kNone);
    }
    for (size_t r = 0; r < rooms.size(); ++r) {
      const bool lit = rooms[r].name == lit_room;
      const Eigen::Vector2d centre = 0.5 * (rooms[r].box.min + rooms[r].box.max);
      drawLabel(painter, theme, qs(riderName(rooms[r].name)), qpoint(view_.toScreen(centre)),
                layout_.label_font_px, lit ? Highlight::kItem : Highlight::kNone, flash);
    }
  } else {
    // The room's places (or, while driving, the destination) with their names.
    std::vector<size_t> shown;
    if (room) shown = room->places;
    for (size_t i = 0; i < places.size(); ++i) {
      const bool in_room = std::find(shown.begin(), shown.end(), i) != shown.end();
      if (!in_room && places[i].name == lit_place) shown.insert(shown.begin(), i);
      if (!in_room)
        drawPlaceDot(painter, theme, qpoint(view_.toScreen(places[i].pose.position())), dot * 0.6,
                     Highlight::kNone);
    }
    // The highlighted label is placed first: it always gets a free spot.
    std::stable_partition(shown.begin(), shown.end(),
                          [&](size_t i) { return places[i].name == lit_place; });
    std::vector<Eigen::Vector2d> anchors;
    std::vector<std::pair<int, int>> sizes;
    std::vector<Highlight> levels;
    for (size_t i : shown) {
      const Highlight h = places[i].name == lit_place ? Highlight::kItem : Highlight::kNone;
      const QSizeF size = labelSize(qs(riderName(places[i].name)), layout_.label_font_px, h);
      anchors.push_back(view_.toScreen(places[i].pose.position()));
      sizes.emplace_back(static_cast<int>(std::ceil(size.width())),
                         static_cast<int>(std::ceil(size.height())));
      levels.push_back(h);
    }
    if (goal && mode == ViewMode::kDrive)  // under the names, which stay readable
      drawDestination(painter, theme, qpoint(view_.toScreen(goal->position())),
                      std::max(14.0, 0.3 * view_.scale));
    const int gap =
        static_cast<int>(mode == ViewMode::kDrive ? std::max(14.0, 0.3 * view_.scale) * 1.4 : dot) +
        4;
    std::vector<Rect> keep_clear;  // the chair stays visible
    if (pose) {
      Eigen::Vector2d lo(1e9, 1e9), hi(-1e9, -1e9);
      for (const auto& p : footprint) {
        lo = lo.cwiseMin(view_.toScreen(p));
        hi = hi.cwiseMax(view_.toScreen(p));
      }
      keep_clear.push_back({static_cast<int>(lo.x()), static_cast<int>(lo.y()),
                            static_cast<int>(hi.x() - lo.x()), static_cast<int>(hi.y() - lo.y())});
    }
    const auto labels = placeLabels(anchors, sizes, area.adjusted(4), gap, keep_clear);
    for (size_t k = 0; k < shown.size(); ++k) {
      drawPlaceDot(painter, theme, qpoint(anchors[k]), dot, levels[k]);
      const Rect& r = labels[k].rect;
      const QRectF rect(r.x, r.y, r.w, r.h);
      drawLabelIn(painter, theme, qs(riderName(places[shown[k]].name)), rect, layout_.label_font_px,
                  levels[k], flash);
      if (mode == ViewMode::kRoom && !switchLeads()) {
        const int id = static_cast<int>(TargetKind::kPlace) * kIdScale + static_cast<int>(shown[k]);
        rect_targets_.emplace_back(rect, id);
        // A place's dot wins over a neighbour's name plate lying across it.
        const QPointF c = qpoint(anchors[k]);
        rect_targets_.insert(rect_targets_.begin(),
                             {QRectF(c.x() - 2 * dot, c.y() - 2 * dot, 4 * dot, 4 * dot), id});
      }
    }
  }

  // The route, the destination and the chair on top.
  std::vector<QPointF> route;
  for (const auto& p : node_.drive().routePoses())
    route.push_back(qpoint(view_.toScreen(p.position())));
  drawRoute(painter, theme, route, std::max(6.0, 0.1 * view_.scale));
  if (pose) {
    std::vector<QPointF> outline;
    for (const auto& p : footprint) outline.push_back(qpoint(view_.toScreen(p)));
    const double size = std::max(12.0, 0.5 * view_.scale);
    drawChair(painter, theme, outline, qpoint(view_.toScreen(pose->position())),
              view_.screenHeading(pose->yaw), size);
  }
  // Where a refused choice was: a cross (the sentence says why).
  if (goal && phase == DriveView::Phase::kRefused) {
    const QPointF at = qpoint(view_.toScreen(goal->position()));
    const double r = std::max(12.0, 0.25 * view_.scale);
    painter.save();
    for (const auto& [colour, width] :
         {std::make_pair(theme.route_casing, 12.0), std::make_pair(theme.destination, 6.0)}) {
      painter.setPen(QPen(qcolor(colour), width, Qt::SolidLine, Qt::RoundCap));
      painter.drawLine(at + QPointF(-r, -r), at + QPointF(r, r));
      painter.drawLine(at + QPointF(-r, r), at + QPointF(r, -r));
    }
    painter.restore();
  }
  // Back to every room (or away from a choice not yet confirmed).
  const bool can_go_back = !switchLeads() && phase != DriveView::Phase::kDriving &&
                           (mode == ViewMode::kRoom || mode == ViewMode::kDrive);
  if (can_go_back) {
    const QString text = "\u25C0 All rooms";
    const QSizeF size = labelSize(text, layout_.label_font_px, Highlight::kNone);
    const QRectF rect(area.x + layout_.padding, area.y + layout_.padding, size.width(),
                      size.height());
    drawLabelIn(painter, theme, text, rect, layout_.label_font_px, Highlight::kNone, flash);
    rect_targets_.emplace_back(rect, static_cast<int>(TargetKind::kBack) * kIdScale);
  }
  // The carer's heading drag.
  if (carer_ == CarerMode::kSetPose && pose_anchor_) {
    painter.setPen(QPen(qcolor(theme.highlight_frame), 6.0));
    painter.drawLine(*pose_anchor_, pose_drag_);
    painter.drawEllipse(*pose_anchor_, 10.0, 10.0);
  }
  painter.restore();
}

void DisplayWindow::paintStatus(QPainter& painter, const Message& message) {
  const Theme& theme = node_.theme();
  const Rect& r = layout_.status;
  painter.fillRect(r.x, r.y, r.w, r.h, qcolor(theme.status_background));
  // Not colour alone: a stop is framed by a thick solid edge, a warning by a dashed one (and
  // the sentence says it: "Stopped: ...").
  if (message.tone != Message::Tone::kInfo) {
    const bool stopped = message.tone == Message::Tone::kStopped;
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(qcolor(theme.status_text), stopped ? 6.0 : 4.0,
                        stopped ? Qt::SolidLine : Qt::DashLine));
    painter.drawRect(QRectF(r.x + 3, r.y + 3, r.w - 6, r.h - 6));
  }
  painter.setPen(qcolor(theme.status_text));
  const double inset = layout_.padding + 8;
  const QRectF text(r.x + inset, r.y + inset, r.w - 2 * inset, r.h - 2 * inset);
  drawFittedText(painter, text, qs(message.status), layout_.status_font_px, 48, true,
                 Qt::AlignLeft | Qt::AlignVCenter);
}

void DisplayWindow::paintList(QPainter& painter) {
  const Theme& theme = node_.theme();
  const ScanView scan = node_.scan();
  const Rect& r = layout_.list;
  painter.fillRect(r.x, r.y, r.w, r.h, qcolor(theme.background));
  painter.setPen(QPen(qcolor(theme.label_border), 2.0));
  painter.drawLine(r.right() - 1, r.y, r.right() - 1, r.bottom());
  std::vector<std::string> items = scan.items;
  int lit = scan.highlighted;
  if (scan.state == ScanView::State::kConfirming) {
    items = {scan.place};
    lit = 0;
  }
  // One size for every item: the largest at which the longest name fits.
  int px = layout_.list_font_px;
  const auto widest = [&](int size) {
    double w = 0;
    for (const auto& item : items)
      w = std::max(
          w,
          QFontMetricsF(riderFont(size, true)).horizontalAdvance("\u25B6 " + qs(riderName(item))));
    return w;
  };
  // Not below 26 px: a longer name is cut short with "..." (the map's plate shows it whole).
  while (px > 26 && widest(px) > r.w - 2 * layout_.padding - 16) --px;
  const double row = 1.7 * layout_.list_font_px;
  const int visible = std::max(1, static_cast<int>((r.h - 2 * layout_.padding) / row));
  const int first =
      std::clamp(lit - visible / 2, 0, std::max(0, static_cast<int>(items.size()) - visible));
  for (int i = first; i < std::min<int>(items.size(), first + visible); ++i) {
    const QRectF cell(r.x + layout_.padding, r.y + layout_.padding + (i - first) * row,
                      r.w - 2 * layout_.padding, row - 6);
    const bool on = i == lit;
    if (on) {
      painter.setBrush(qcolor(theme.highlight_background));
      painter.setPen(QPen(qcolor(flashOn(clock_.elapsed() / 1000.0) ? theme.highlight_frame
                                                                    : theme.highlight_frame_alt),
                          6.0));
      painter.drawRect(cell);
      // The time left until the highlight moves on: a bar shrinking along the bottom edge.
      if (scan.step_time > 0) {
        const double share = std::clamp(scan.time_left / scan.step_time, 0.0, 1.0);
        painter.fillRect(QRectF(cell.x() + 6, cell.bottom() - 12, (cell.width() - 12) * share, 8),
                         qcolor(theme.highlight_text));
      }
    }
    painter.setPen(qcolor(on ? theme.highlight_text : theme.text));
    painter.setFont(riderFont(px, on));
    const QRectF text_box = cell.adjusted(8, 0, -4, -6);
    const QString text = QFontMetricsF(riderFont(px, on))
                             .elidedText((on ? "\u25B6 " : "  ") + qs(riderName(items[i])),
                                         Qt::ElideRight, text_box.width());
    painter.drawText(text_box, Qt::AlignVCenter | Qt::AlignLeft, text);
  }
}

void DisplayWindow::paintPrompt(QPainter& painter, const Message& message) {
  const Theme& theme = node_.theme();
  const Rect& r = layout_.prompt;
  painter.fillRect(r.x, r.y, r.w, r.h, qcolor(theme.background));
  painter.setPen(QPen(qcolor(theme.label_border), 2.0));
  painter.drawLine(r.x, r.y, r.right(), r.y);
  // The carer's button: small, labelled, held to open (a ring shows the hold).
  const Rect& c = layout_.carer_button;
  painter.setBrush(Qt::NoBrush);
  painter.setPen(QPen(qcolor(theme.label_border), 2.0));
  painter.drawRect(c.x, c.y, c.w, c.h);
  painter.setPen(qcolor(theme.text));
  painter.setFont(riderFont(std::max(14, c.h / 4)));
  painter.drawText(QRectF(c.x, c.y, c.w, c.h), Qt::AlignCenter, "Carer");
  if (holding_carer_) {
    const double share = carer_hold_.elapsed() / (1000.0 * node_.config().display.carer_hold);
    drawDwellRing(painter, theme, QPointF(c.centreX(), c.centreY()), c.w * 0.6,
                  std::min(1.0, share));
  }
  double right = r.right() - layout_.padding;
  if (message.show_go && carer_ == CarerMode::kClosed) {
    const Rect& g = layout_.go_button;
    painter.setBrush(qcolor(theme.button_background));
    painter.setPen(QPen(qcolor(theme.button_frame), 6.0));
    painter.drawRect(QRectF(g.x, g.y, g.w, g.h));
    painter.setPen(qcolor(theme.button_text));
    painter.setFont(riderFont(layout_.prompt_font_px + 6, true));
    painter.drawText(QRectF(g.x, g.y, g.w, g.h), Qt::AlignCenter, "\u25B6 Go");
    rect_targets_.emplace_back(QRectF(g.x, g.y, g.w, g.h),
                               static_cast<int>(TargetKind::kGo) * kIdScale);
    right = g.x - layout_.padding;
  }
  std::string prompt = message.prompt;
  if (carer_ == CarerMode::kSetPose)
    prompt = "Press where the chair is and drag the way it faces.";
  else if (carer_ == CarerMode::kDeletePlace)
    prompt = "Open a room and choose the place to delete.";
  painter.setPen(qcolor(theme.text));
  const double left = c.right() + 2 * layout_.padding;
  drawFittedText(painter, QRectF(left, r.y + 4, right - left, r.h - 8), qs(prompt),
                 layout_.prompt_font_px, 28, false, Qt::AlignLeft | Qt::AlignVCenter);
}

void DisplayWindow::paintStop(QPainter& painter) {
  const Theme& theme = node_.theme();
  const Rect& s = layout_.stop;
  painter.fillRect(s.x, s.y, s.w, s.h, qcolor(theme.stop_background));
  // A stop sign's octagon above the word; the word as large as the area's width allows.
  const QPointF centre(s.centreX(), s.centreY() - 0.3 * s.w);
  painter.setPen(Qt::NoPen);
  painter.setBrush(qcolor(theme.stop_text));
  painter.drawPolygon(signShape(centre, 0.3 * s.w, 8, M_PI / 8));
  int px = layout_.stop_font_px;
  while (px > 24 && QFontMetricsF(riderFont(px, true)).horizontalAdvance("STOP") > 0.86 * s.w) --px;
  painter.setPen(qcolor(theme.stop_text));
  painter.setFont(riderFont(px, true));
  painter.drawText(QRectF(s.x, s.centreY() + 0.05 * s.w, s.w, 1.4 * px), Qt::AlignCenter, "STOP");
}

// ---- the carer's tools ------------------------------------------------------------------------

void DisplayWindow::buildCarerPanel() {
  carer_panel_ = new QWidget(this);
  auto* column = new QVBoxLayout(carer_panel_);
  const auto button = [&](const QString& text, std::vector<QPushButton*>& group, auto action) {
    auto* b = new QPushButton(text, carer_panel_);
    connect(b, &QPushButton::clicked, this, action);
    column->addWidget(b);
    group.push_back(b);
    return b;
  };
  carer_note_ = new QLabel(carer_panel_);
  carer_note_->setWordWrap(true);
  column->addWidget(carer_note_);
  button("Set position", tool_buttons_, [this] { setCarerMode(CarerMode::kSetPose); });
  button("Save place here", tool_buttons_, [this] { setCarerMode(CarerMode::kSavePlace); });
  button("Delete a place", tool_buttons_, [this] { setCarerMode(CarerMode::kDeletePlace); });
  theme_button_ = button("", tool_buttons_, [this] {
    node_.setTheme(node_.theme().name == "dark" ? "light" : "dark");
    setCarerMode(CarerMode::kTools);
  });
  orientation_button_ = button("", tool_buttons_, [this] {
    node_.setOrientation(node_.orientation() == Orientation::kNorthUp ? Orientation::kChairUp
                                                                      : Orientation::kNorthUp);
    setCarerMode(CarerMode::kTools);
  });
  speech_button_ = button("", tool_buttons_, [this] {
    node_.setSpeech(!node_.speechOn());
    setCarerMode(CarerMode::kTools);
  });
  button("Close", tool_buttons_, [this] { setCarerMode(CarerMode::kClosed); });

  name_edit_ = new QLineEdit(carer_panel_);
  name_edit_->setPlaceholderText("Name of the place");
  column->addWidget(name_edit_);
  room_box_ = new QComboBox(carer_panel_);
  room_box_->setEditable(true);
  column->addWidget(room_box_);
  button("Save", save_buttons_, [this] {
    const std::string problem = node_.savePlaceHere(name_edit_->text().toStdString(),
                                                    room_box_->currentText().toStdString());
    if (problem.empty()) {
      setCarerMode(CarerMode::kTools);
      carer_note_->setText("Saved.");
    } else {
      carer_note_->setText(qs("Not saved: " + problem + "."));
    }
  });
  button("Cancel", save_buttons_, [this] { setCarerMode(CarerMode::kTools); });
  delete_button_ = button("Delete", delete_buttons_, [this] {
    const std::string problem = node_.deletePlace(delete_candidate_);
    setCarerMode(CarerMode::kTools);
    carer_note_->setText(qs(problem.empty() ? "Deleted." : "Not deleted: " + problem + "."));
  });
  button("Keep it", delete_buttons_, [this] { setCarerMode(CarerMode::kTools); });
  column->addStretch();
  setCarerMode(CarerMode::kClosed);
}

void DisplayWindow::setCarerMode(CarerMode mode) {
  carer_ = mode;
  const bool tools = mode == CarerMode::kTools, save = mode == CarerMode::kSavePlace,
             remove = mode == CarerMode::kDeletePlace;
  for (auto* b : tool_buttons_) b->setVisible(tools);
  for (auto* b : save_buttons_) b->setVisible(save);
  for (auto* b : delete_buttons_) b->setVisible(remove);
  name_edit_->setVisible(save);
  room_box_->setVisible(save);
  carer_panel_->setVisible(mode != CarerMode::kClosed);
  theme_button_->setText(node_.theme().name == "dark" ? "Light theme" : "Dark theme");
  orientation_button_->setText(node_.orientation() == Orientation::kNorthUp ? "Chair up"
                                                                            : "North up");
  speech_button_->setText(node_.speechOn() ? "Speech off" : "Speech on");
  carer_note_->setText(tools                         ? "Carer's tools"
                       : mode == CarerMode::kSetPose ? "Set position"
                       : save                        ? "Save place here"
                       : remove                      ? "Delete a place"
                                                     : "");
  if (save) {
    name_edit_->clear();
    room_box_->clear();
    for (const auto& room : node_.rooms()) room_box_->addItem(qs(room.name));
    const auto& pose = node_.chairPose();
    const int here = pose ? roomAt(node_.rooms(), pose->position()) : -1;
    if (here >= 0) room_box_->setCurrentIndex(here);
    name_edit_->setFocus();
  }
  if (remove) {
    delete_candidate_.clear();
    delete_button_->setText("Delete");
    delete_button_->setEnabled(false);
  }
  pose_anchor_.reset();
  update();
}

void DisplayWindow::placeCarerPanel() {
  if (carer_ == CarerMode::kClosed) return;
  const Theme& t = node_.theme();
  const Rect& r = layout_.list;
  carer_panel_->setGeometry(r.x, r.y, r.w, r.h);
  // Fixed heights: every control as tall as two lines of its text.
  const int font = std::max(22, layout_.label_font_px);
  for (auto* child : carer_panel_->findChildren<QWidget*>()) child->setFixedHeight(font * 2);
  const QString style =
      QString(
          "QWidget { background: %1; color: %2; font-family: 'DejaVu Sans'; font-size: %3px; }"
          "QPushButton { border: 3px solid %4; padding: 8px; }"
          "QPushButton:disabled { color: %2; border-style: dashed; }"
          "QLineEdit, QComboBox { border: 3px solid %4; padding: 4px; }")
          .arg(qs(toHex(t.background)), qs(toHex(t.text)))
          .arg(font)
          .arg(qs(toHex(t.label_border)));
  if (carer_panel_->styleSheet() != style) carer_panel_->setStyleSheet(style);
}

}  // namespace wheelchair_display
