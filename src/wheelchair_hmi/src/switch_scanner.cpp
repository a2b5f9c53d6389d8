#include <wheelchair_hmi/switch_scanner.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace wheelchair_hmi {

std::string ScannerOptions::validate() const {
  wheelchair_core::ConfigChecks checks;
  checks.positive("scan_interval", scan_interval)
      .positive("confirm_timeout", confirm_timeout)
      .check(item_cycles >= 1,
             "item_cycles must be at least 1 (got " + std::to_string(item_cycles) + ")");
  return checks.result();
}

void readScannerOptions(wheelchair_core::ConfigReader& reader, ScannerOptions& options) {
  reader.read("scan_interval", options.scan_interval);
  reader.read("confirm_timeout", options.confirm_timeout);
  reader.read("item_cycles", options.item_cycles);
}

SwitchScanner::SwitchScanner(std::vector<Place> places, ScannerOptions options)
    : places_(std::move(places)), options_(options) {
  if (places_.empty()) throw std::invalid_argument("switch scanner needs at least one place");
  const std::string problem = options_.validate();
  if (!problem.empty()) throw std::invalid_argument("switch scanner: " + problem);
  for (size_t i = 0; i < places_.size(); ++i) {
    const auto it = std::find(group_names_.begin(), group_names_.end(), places_[i].room);
    if (it == group_names_.end()) {
      group_names_.push_back(places_[i].room);
      group_members_.push_back({i});
    } else {
      group_members_[it - group_names_.begin()].push_back(i);
    }
  }
  // Larger rooms first: minimizes the mean number of room highlights (stable for ties).
  std::vector<size_t> order(group_names_.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [this](size_t a, size_t b) {
    return group_members_[a].size() > group_members_[b].size();
  });
  std::vector<std::string> names;
  std::vector<std::vector<size_t>> members;
  for (size_t g : order) {
    names.push_back(group_names_[g]);
    members.push_back(group_members_[g]);
  }
  group_names_ = std::move(names);
  group_members_ = std::move(members);
}

ScanOutput SwitchScanner::highlight() {
  ScanOutput out;
  out.kind = ScanOutput::Kind::kHighlight;
  if (phase_ == Phase::kGroups) {
    out.group = group_names_[group_];
    out.text = group_names_[group_] + "?";
  } else {
    out.place = &places_[group_members_[group_][item_]];
    out.group = group_names_[group_];
    out.text = out.place->name + "?";
  }
  return out;
}

ScanOutput SwitchScanner::enterGroups(double now) {
  phase_ = Phase::kGroups;
  group_ = 0;
  last_step_ = now;
  return highlight();
}

ScanOutput SwitchScanner::start(double now) { return enterGroups(now); }

ScanOutput SwitchScanner::tick(double now) {
  if (phase_ == Phase::kConfirm) {
    if (now - last_step_ < options_.confirm_timeout) return {};
    enterGroups(now);
    ScanOutput out = highlight();
    out.kind = ScanOutput::Kind::kCancelled;
    out.text = "Not confirmed. " + out.text;
    return out;
  }
  if (phase_ == Phase::kDriving || now - last_step_ < options_.scan_interval) return {};
  last_step_ = now;
  if (phase_ == Phase::kGroups) {
    group_ = (group_ + 1) % group_names_.size();
    return highlight();
  }
  const size_t count = group_members_[group_].size();
  if (++item_steps_ >= options_.item_cycles * static_cast<int>(count)) return enterGroups(now);
  item_ = (item_ + 1) % count;
  return highlight();
}

ScanOutput SwitchScanner::press(double now) {
  last_step_ = now;
  ScanOutput out;
  switch (phase_) {
    case Phase::kGroups:
      item_ = 0;
      item_steps_ = 0;
      if (group_members_[group_].size() > 1) {
        phase_ = Phase::kItems;
        return highlight();
      }
      [[fallthrough]];  // a room with one place: straight to the confirmation
    case Phase::kItems:
      phase_ = Phase::kConfirm;
      out.kind = ScanOutput::Kind::kAskConfirm;
      out.place = &places_[group_members_[group_][item_]];
      out.text = "Go to " + out.place->name + "? Press to confirm.";
      return out;
    case Phase::kConfirm:
      phase_ = Phase::kDriving;
      out.kind = ScanOutput::Kind::kGo;
      out.place = &places_[group_members_[group_][item_]];
      out.text = "Going to " + out.place->name + ". Press to stop.";
      return out;
    case Phase::kDriving:
      enterGroups(now);
      out = highlight();
      out.kind = ScanOutput::Kind::kStop;
      out.text = "Stopped. " + out.text;
      return out;
  }
  return out;
}

ScanOutput SwitchScanner::finished(double now) {
  if (phase_ != Phase::kDriving) return {};
  return enterGroups(now);
}

void SwitchScanner::driving(double now) {
  phase_ = Phase::kDriving;
  last_step_ = now;
}

ScanEffort measureScanEffort(const std::vector<Place>& places, const ScannerOptions& options) {
  ScanEffort effort;
  for (size_t target = 0; target < places.size(); ++target) {
    SwitchScanner scanner(places, options);
    double now = 0.0;
    ScanOutput out = scanner.start(now);
    int steps = 1, presses = 0;
    const Place* wanted = &scanner.places()[target];
    while (out.kind != ScanOutput::Kind::kGo) {
      if (steps + presses > 10000) throw std::logic_error("scanner never offered the target");
      const bool in_room = out.kind == ScanOutput::Kind::kHighlight && out.place == nullptr &&
                           out.group == wanted->room;
      const bool is_target = out.place == wanted && (out.kind == ScanOutput::Kind::kHighlight ||
                                                     out.kind == ScanOutput::Kind::kAskConfirm);
      if (in_room || is_target) {
        ++presses;
        out = scanner.press(now);
        if (out.kind == ScanOutput::Kind::kHighlight) ++steps;
        continue;
      }
      now += options.scan_interval;
      out = scanner.tick(now);
      if (out.kind == ScanOutput::Kind::kHighlight) ++steps;
    }
    effort.mean_steps += steps;
    effort.max_steps = std::max(effort.max_steps, steps);
    effort.max_presses = std::max(effort.max_presses, presses);
  }
  effort.mean_steps /= static_cast<double>(places.size());
  effort.linear_mean_steps = 0.5 * (static_cast<double>(places.size()) + 1.0);
  return effort;
}

}  // namespace wheelchair_hmi
