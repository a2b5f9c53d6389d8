// The localizer's verdict in the project's vocabulary: the state it is in, the numbers behind it
// and the technical reason. The localizer's core returns it; wheelchair_ros converts it to
// wheelchair_msgs/LocalizationStatus (/localization/status). Consumers branch on the state,
// never on the text.
#pragma once

#include <cmath>
#include <string>

namespace wheelchair_core {

/// The states of wheelchair_msgs/LocalizationStatus, in its order.
enum class LocalizationState {
  kUninitialized,  ///< no initial pose and no global localization yet
  kLocalizing,     ///< initialized, waiting for the first scan to confirm the pose
  kLocalized,      ///< the estimate can be driven on
  kAmbiguous,      ///< several pose hypotheses of similar weight
  kUncertain,      ///< one hypothesis, but its covariance exceeds the limits
  kMisfit,         ///< the scans do not fit the map at the estimate (kidnapped or lost)
  kNoData,         ///< no map, or no usable scan or odometry / tf
};

struct LocalizationStatus {
  LocalizationState state = LocalizationState::kUninitialized;
  std::string detail;  ///< the technical reason with its numbers ("" when localized)
  // The numbers behind the verdict (NaN / 0 where not applicable).
  double position_std = NAN;     ///< [m] largest std-dev of the x-y covariance
  double heading_std = NAN;      ///< [rad]
  double inlier_fraction = NAN;  ///< share of echoes that fit the map at the estimate
  double mean_fit = NAN;         ///< mean inlier share over the recent window
  int hypotheses = 0;            ///< pose clusters
  double best_weight = NAN;      ///< weight share of the best cluster
  int particles = 0;

  bool localized() const { return state == LocalizationState::kLocalized; }
};

/// What the rider is told in `state`: short, without frames or coordinates.
inline const char* riderSentence(LocalizationState state) {
  switch (state) {
    case LocalizationState::kUninitialized:
      return "Position not known yet.";
    case LocalizationState::kLocalizing:
      return "Finding the position.";
    case LocalizationState::kLocalized:
      return "Position known.";
    case LocalizationState::kAmbiguous:
      return "Several places look alike: position not certain.";
    case LocalizationState::kUncertain:
      return "Position not certain enough.";
    case LocalizationState::kMisfit:
      return "Surroundings do not match the map.";
    case LocalizationState::kNoData:
      return "Map or sensor data missing.";
  }
  return "";
}

}  // namespace wheelchair_core
