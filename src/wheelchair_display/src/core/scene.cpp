#include <wheelchair_display/scene.h>

#include <algorithm>

namespace wheelchair_display {

std::vector<RoomArea> roomAreas(const std::vector<wheelchair_hmi::Place>& places, double pad) {
  std::vector<RoomArea> rooms;
  for (size_t i = 0; i < places.size(); ++i) {
    int r = roomNamed(rooms, places[i].room);
    if (r < 0) {
      rooms.push_back({places[i].room, {}, {}});
      r = static_cast<int>(rooms.size()) - 1;
    }
    rooms[r].places.push_back(i);
  }
  for (auto& room : rooms) {
    std::vector<Eigen::Vector2d> points;
    for (size_t i : room.places) points.push_back(places[i].pose.position());
    room.box = wheelchair_core::boundingBox(points);
    room.box.min -= Eigen::Vector2d(pad, pad);
    room.box.max += Eigen::Vector2d(pad, pad);
  }
  return rooms;
}

int roomAt(const std::vector<RoomArea>& rooms, const Eigen::Vector2d& p) {
  int best = -1;
  double best_area = 1e300;
  for (size_t i = 0; i < rooms.size(); ++i) {
    const auto& b = rooms[i].box;
    if (p.x() < b.min.x() || p.y() < b.min.y() || p.x() > b.max.x() || p.y() > b.max.y()) continue;
    const double area = (b.max - b.min).prod();
    if (area < best_area) {
      best_area = area;
      best = static_cast<int>(i);
    }
  }
  return best;
}

int roomNamed(const std::vector<RoomArea>& rooms, const std::string& name) {
  for (size_t i = 0; i < rooms.size(); ++i)
    if (rooms[i].name == name) return static_cast<int>(i);
  return -1;
}

wheelchair_core::Box knownBounds(const wheelchair_core::OccupancyMap& map) {
  int lo_x = map.width, lo_y = map.height, hi_x = -1, hi_y = -1;
  for (int iy = 0; iy < map.height; ++iy)
    for (int ix = 0; ix < map.width; ++ix)
      if (map.at(ix, iy) != wheelchair_core::kUnknown) {
        lo_x = std::min(lo_x, ix);
        hi_x = std::max(hi_x, ix);
        lo_y = std::min(lo_y, iy);
        hi_y = std::max(hi_y, iy);
      }
  wheelchair_core::Box box;
  if (hi_x < 0) return box;
  box.min = {map.origin_x + lo_x * map.resolution, map.origin_y + lo_y * map.resolution};
  box.max = {map.origin_x + (hi_x + 1) * map.resolution,
             map.origin_y + (hi_y + 1) * map.resolution};
  return box;
}

std::vector<LabelBox> placeLabels(const std::vector<Eigen::Vector2d>& anchors,
                                  const std::vector<std::pair<int, int>>& sizes, const Rect& bounds,
                                  int gap, const std::vector<Rect>& keep_clear) {
  std::vector<LabelBox> labels;
  for (size_t i = 0; i < anchors.size(); ++i) {
    const int w = sizes[i].first, h = sizes[i].second;
    const int ax = static_cast<int>(anchors[i].x()), ay = static_cast<int>(anchors[i].y());
    const Rect candidates[] = {{ax + gap, ay - h / 2, w, h},     {ax - gap - w, ay - h / 2, w, h},
                               {ax - w / 2, ay - gap - h, w, h}, {ax - w / 2, ay + gap, w, h},
                               {ax + gap, ay - gap - h, w, h},   {ax - gap - w, ay - gap - h, w, h},
                               {ax + gap, ay + gap, w, h},       {ax - gap - w, ay + gap, w, h}};
    const auto inside = [&](const Rect& r) {
      return r.x >= bounds.x && r.y >= bounds.y && r.right() <= bounds.right() &&
             r.bottom() <= bounds.bottom();
    };
    const auto free = [&](const Rect& r) {
      return std::none_of(labels.begin(), labels.end(),
                          [&](const LabelBox& l) { return l.rect.intersects(r); }) &&
             std::none_of(keep_clear.begin(), keep_clear.end(),
                          [&](const Rect& k) { return k.intersects(r); });
    };
    LabelBox chosen{candidates[0], true};
    bool found = false;
    for (const Rect& r : candidates) {
      if (inside(r) && free(r)) {
        chosen = {r, false};
        found = true;
        break;
      }
    }
    if (!found) {
      for (const Rect& r : candidates)
        if (inside(r)) {
          chosen = {r, true};
          break;
        }
    }
    labels.push_back(chosen);
  }
  return labels;
}

std::vector<Eigen::Vector2d> viewFrame(const wheelchair_core::Box& overview,
                                       const wheelchair_core::Polygon* chair,
                                       const std::vector<wheelchair_core::Pose2D>& route,
                                       const wheelchair_core::Pose2D* goal, const RoomArea* room) {
  std::vector<Eigen::Vector2d> frame;
  if (goal) {
    if (chair) frame.insert(frame.end(), chair->begin(), chair->end());
    for (const auto& p : route) frame.push_back(p.position());
    frame.push_back(goal->position());
    return frame;
  }
  if (room) return {room->box.min, room->box.max};
  if (!overview.empty()) return {overview.min, overview.max};
  if (chair) frame.insert(frame.end(), chair->begin(), chair->end());
  return frame;
}

}  // namespace wheelchair_display
