#include "map_painter.h"

#include <QFontMetricsF>
#include <QPainterPath>
#include <QPolygonF>
#include <QTransform>

#include <cmath>

namespace wheelchair_display {
namespace {

double labelScale(Highlight h) { return h == Highlight::kItem ? 1.35 : 1.0; }

}  // namespace

QFont riderFont(int pixels, bool bold) {
  QFont font("DejaVu Sans");
  font.setPixelSize(pixels);
  font.setBold(bold);
  return font;
}

void drawGrid(QPainter& painter, const ViewTransform& view,
              const wheelchair_core::OccupancyMap& grid, const QImage& image) {
  if (image.isNull()) return;
  // Image pixel (u, v) has its top-left corner at world (origin_x + u r, origin_y + (H - v) r).
  const auto corner = [&](double u, double v) {
    return view.toScreen(
        {grid.origin_x + u * grid.resolution, grid.origin_y + (grid.height - v) * grid.resolution});
  };
  const Eigen::Vector2d s0 = corner(0, 0), du = corner(1, 0) - s0, dv = corner(0, 1) - s0;
  painter.save();
  painter.setTransform(QTransform(du.x(), du.y(), dv.x(), dv.y(), s0.x(), s0.y()), true);
  painter.setRenderHint(QPainter::SmoothPixmapTransform, false);
  painter.drawImage(QPointF(0, 0), image);
  painter.restore();
}

QSizeF labelSize(const QString& text, int font_px, Highlight highlight) {
  const int px = static_cast<int>(std::lround(font_px * labelScale(highlight)));
  const QFontMetricsF metrics(riderFont(px, highlight == Highlight::kItem));
  const double pad = 0.35 * px;
  return {metrics.horizontalAdvance(text) + 2 * pad, metrics.height() + pad};
}

void drawLabelIn(QPainter& painter, const Theme& theme, const QString& text, const QRectF& rect,
                 int font_px, Highlight highlight, bool flash_on) {
  const int px = static_cast<int>(std::lround(font_px * labelScale(highlight)));
  painter.save();
  const bool lit = highlight == Highlight::kItem;
  painter.setBrush(qcolor(lit ? theme.highlight_background : theme.label_background));
  const double frame = lit ? std::max(6.0, 0.22 * px) : 2.0;
  const Rgb edge =
      lit ? (flash_on ? theme.highlight_frame : theme.highlight_frame_alt)
          : (highlight == Highlight::kGroup ? theme.highlight_frame : theme.label_border);
  painter.setPen(QPen(qcolor(edge), highlight == Highlight::kGroup ? 4.0 : frame));
  painter.drawRect(rect);
  painter.setPen(qcolor(lit ? theme.highlight_text : theme.label_text));
  painter.setFont(riderFont(px, lit));
  painter.drawText(rect, Qt::AlignCenter, text);
  painter.restore();
}

QRectF drawLabel(QPainter& painter, const Theme& theme, const QString& text, const QPointF& at,
                 int font_px, Highlight highlight, bool flash_on) {
  const QSizeF size = labelSize(text, font_px, highlight);
  const QRectF rect(at.x() - size.width() / 2, at.y() - size.height() / 2, size.width(),
                    size.height());
  drawLabelIn(painter, theme, text, rect, font_px, highlight, flash_on);
  return rect;
}

void drawPlaceDot(QPainter& painter, const Theme& theme, const QPointF& at, double radius,
                  Highlight highlight) {
  painter.save();
  const bool lit = highlight == Highlight::kItem;
  const double r = lit ? 1.6 * radius : radius;
  painter.setPen(QPen(qcolor(lit ? theme.highlight_frame : theme.label_border), lit ? 4.0 : 2.0));
  painter.setBrush(qcolor(lit ? theme.highlight_background : theme.label_background));
  painter.drawEllipse(at, r, r);
  painter.restore();
}

void drawRoute(QPainter& painter, const Theme& theme, const std::vector<QPointF>& points,
               double width) {
  if (points.size() < 2) return;
  QPolygonF line;
  for (const auto& p : points) line << p;
  painter.save();
  painter.setBrush(Qt::NoBrush);
  painter.setPen(
      QPen(qcolor(theme.route_casing), width + 4, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
  painter.drawPolyline(line);
  painter.setPen(QPen(qcolor(theme.route), width, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
  painter.drawPolyline(line);
  painter.restore();
}

void drawDestination(QPainter& painter, const Theme& theme, const QPointF& at, double radius) {
  painter.save();
  painter.setBrush(Qt::NoBrush);
  for (const auto& [colour, width] :
       {std::make_pair(theme.route_casing, 9.0), std::make_pair(theme.destination, 5.0)}) {
    painter.setPen(QPen(qcolor(colour), width));
    painter.drawEllipse(at, radius, radius);
    painter.drawEllipse(at, radius * 0.45, radius * 0.45);
    painter.drawLine(at + QPointF(-radius * 1.3, 0), at + QPointF(radius * 1.3, 0));
    painter.drawLine(at + QPointF(0, -radius * 1.3), at + QPointF(0, radius * 1.3));
  }
  painter.restore();
}

void drawChair(QPainter& painter, const Theme& theme, const std::vector<QPointF>& outline,
               const QPointF& centre, double heading, double size) {
  painter.save();
  QPolygonF body;
  for (const auto& p : outline) body << p;
  painter.setPen(
      QPen(qcolor(theme.chair_outline), 3.0, Qt::SolidLine, Qt::SquareCap, Qt::MiterJoin));
  painter.setBrush(qcolor(theme.chair_fill));
  painter.drawPolygon(body);
  // The heading: an arrow head inside the body, pointing the way the chair faces.
  const QPointF ahead(std::cos(heading), -std::sin(heading)),
      side(std::sin(heading), std::cos(heading));
  QPolygonF arrow;
  arrow << centre + ahead * size * 0.55 << centre - ahead * size * 0.15 + side * size * 0.3
        << centre - ahead * size * 0.15 - side * size * 0.3;
  painter.setBrush(qcolor(theme.chair_outline));
  painter.drawPolygon(arrow);
  painter.restore();
}

void drawDwellRing(QPainter& painter, const Theme& theme, const QPointF& at, double radius,
                   double progress) {
  if (progress <= 0.0) return;
  painter.save();
  painter.setBrush(Qt::NoBrush);
  const QRectF box(at.x() - radius, at.y() - radius, 2 * radius, 2 * radius);
  painter.setPen(QPen(qcolor(theme.route_casing), 12.0, Qt::SolidLine, Qt::FlatCap));
  painter.drawEllipse(box);
  painter.setPen(QPen(qcolor(theme.ring), 8.0, Qt::SolidLine, Qt::FlatCap));
  painter.drawArc(box, 90 * 16, -static_cast<int>(std::lround(progress * 360 * 16)));
  painter.restore();
}

}  // namespace wheelchair_display
