// Drawing the map view with QPainter: the map and the live obstacle layer, rooms and places
// (the highlighted one framed, larger and with a flashing edge, never by colour alone), the
// route, the destination, the chair's footprint with its heading, and the dwell ring.
#pragma once

#include <wheelchair_core/occupancy_map.h>
#include <wheelchair_core/polygon.h>
#include <wheelchair_display/map_view.h>
#include <wheelchair_display/theme.h>

#include <QColor>
#include <QFont>
#include <QImage>
#include <QPainter>
#include <QRectF>
#include <QString>

#include <string>
#include <vector>

namespace wheelchair_display {

inline QColor qcolor(const Rgb& c) { return QColor(c.r, c.g, c.b); }

/// A font of the project's family (DejaVu Sans, from Debian) at `pixels`.
QFont riderFont(int pixels, bool bold = false);

/// Draws `image` (a grid's cells, top row first) where `grid` lies in the world.
void drawGrid(QPainter& painter, const ViewTransform& view,
              const wheelchair_core::OccupancyMap& grid, const QImage& image);

/// How strongly an item stands out: not, as a member of the highlighted room, or itself.
enum class Highlight { kNone, kGroup, kItem };

/// A name on a plate; highlighted plates are larger, filled, and framed by a thick edge whose
/// colour alternates with `flash_on`. Returns the plate's rectangle (a pointer target).
QRectF drawLabel(QPainter& painter, const Theme& theme, const QString& text, const QPointF& at,
                 int font_px, Highlight highlight, bool flash_on);
/// The same plate at a chosen rectangle (label placement done by the caller).
void drawLabelIn(QPainter& painter, const Theme& theme, const QString& text, const QRectF& rect,
                 int font_px, Highlight highlight, bool flash_on);
/// The plate size for `text`.
QSizeF labelSize(const QString& text, int font_px, Highlight highlight);

void drawPlaceDot(QPainter& painter, const Theme& theme, const QPointF& at, double radius,
                  Highlight highlight);
void drawRoute(QPainter& painter, const Theme& theme, const std::vector<QPointF>& points,
               double width);
/// A target sign (rings and a cross) at the destination.
void drawDestination(QPainter& painter, const Theme& theme, const QPointF& at, double radius);
/// The footprint polygon (screen points) with an arrow along `heading` (screen angle).
void drawChair(QPainter& painter, const Theme& theme, const std::vector<QPointF>& outline,
               const QPointF& centre, double heading, double size);
/// The dwell ring at the pointer, filled to `progress` (0..1).
void drawDwellRing(QPainter& painter, const Theme& theme, const QPointF& at, double radius,
                   double progress);

}  // namespace wheelchair_display
