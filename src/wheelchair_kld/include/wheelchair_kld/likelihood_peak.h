// The peak of a scan's likelihood near a pose, by a pattern search (the published estimate's
// last step: on a real map the posterior mean of a broad, tempered likelihood sits centimetres
// off the peak where the scan fits best; measured with `replay --reference-fit`).
#pragma once

#include <mrpt/math/TPose2D.h>
#include <wheelchair_kld/measurement_model.h>

namespace wheelchair_kld {

struct PeakSearch {
  double step_xy = 0.02;        ///< first step [m], halved until min_step_xy
  double step_theta = 0.0087;   ///< first step [rad] (0.5 deg), halved alike
  double min_step_xy = 0.0025;  ///< [m]
  double max_xy = 0.2;          ///< the peak is searched within this of the start [m]
  double max_theta = 0.06;      ///< ... and this in heading [rad]
  int max_evaluations = 200;
};

/// The pose near `start` (within max_xy / max_theta) where model.logLikelihood is highest, by
/// compass search: the best of the 6 moves (+-x, +-y, +-yaw) is taken while it improves, the
/// steps halve when none does, until min_step_xy. Deterministic; at most max_evaluations calls.
mrpt::math::TPose2D likelihoodPeakNear(const MeasurementModel& model,
                                       const mrpt::math::TPose2D& start, const PeakSearch& search);

}  // namespace wheelchair_kld
