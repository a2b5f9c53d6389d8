#include <wheelchair_hmi/scan_state.h>

#include <algorithm>
#include <cmath>

namespace wheelchair_hmi {

bool ScanState::sameShown(const ScanState& o) const {
  return state == o.state && items == o.items && highlighted == o.highlighted && room == o.room &&
         place == o.place && step_time == o.step_time && sentence == o.sentence;
}

ScanState scanState(const SwitchScanner& scanner, double now, const std::string& goal) {
  using Phase = SwitchScanner::Phase;
  ScanState s;
  const auto& places = scanner.places();
  const auto& members = scanner.groupMembers()[scanner.group()];
  const std::string& room = scanner.groups()[scanner.group()];
  const auto& options = scanner.options();
  const double since = now - scanner.lastStep();
  switch (scanner.phase()) {
    case Phase::kGroups:
      s.state = ScanState::Kind::kRooms;
      s.items = scanner.groups();
      s.highlighted = static_cast<int>(scanner.group());
      s.room = room;
      s.step_time = options.scan_interval;
      break;
    case Phase::kItems:
      s.state = ScanState::Kind::kPlaces;
      for (size_t m : members) s.items.push_back(places[m].name);
      s.highlighted = static_cast<int>(scanner.item());
      s.room = room;
      s.place = places[members[scanner.item()]].name;
      s.step_time = options.scan_interval;
      break;
    case Phase::kConfirm:
      s.state = ScanState::Kind::kConfirming;
      s.room = room;
      s.place = places[members[scanner.item()]].name;
      s.items = {s.place};
      s.highlighted = 0;
      s.step_time = options.confirm_timeout;
      break;
    case Phase::kDriving:
      s.state = ScanState::Kind::kDriving;
      s.place = goal;
      if (!goal.empty()) s.items = {goal};
      return s;
  }
  s.time_left = std::clamp(s.step_time - since, 0.0, s.step_time);
  return s;
}

std::string placeAt(const std::vector<Place>& places, const wheelchair_core::Pose2D& pose,
                    double tolerance) {
  for (const auto& p : places)
    if (std::hypot(p.pose.x - pose.x, p.pose.y - pose.y) <= tolerance &&
        std::abs(wheelchair_core::angleDifference(p.pose.yaw, pose.yaw)) <= 0.05)
      return p.name;
  return "";
}

}  // namespace wheelchair_hmi
