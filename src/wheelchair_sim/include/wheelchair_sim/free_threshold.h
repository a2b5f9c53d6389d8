// What blocks in the ground-truth grid.
#pragma once

namespace wheelchair_sim {

/// A cell blocks the chair and reflects the laser when its probability of being free (MRPT's
/// cell value) is below this: occupied cells do, unknown (0.5) and free cells do not.
constexpr float kFreeThreshold = 0.45f;

}  // namespace wheelchair_sim
