#include <wheelchair_core/ray_trace.h>
#include <wheelchair_mapping/bayes_mapper.h>
#include <wheelchair_mapping/scan_checks.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace wheelchair_mapping {
namespace {

using Grid = mrpt::maps::COccupancyGridMap2D;
using LogOdds = mrpt::maps::CLogOddsGridMap2D<Grid::cellType>;

/// MRPT's cells hold round(16 ln(p / (1 - p))) (CLogOddsGridMapLUT's LOGODD_K). Its own p2l()
/// first truncates p to a multiple of 1/127, so the conversion is done here, more precisely.
constexpr double kLogOddsScale = 16.0;

Grid::cellType toCellLogOdds(double p) {
  const long l = std::lround(kLogOddsScale * std::log(p / (1.0 - p)));
  return static_cast<Grid::cellType>(
      std::clamp<long>(l, Grid::OCCGRID_CELLTYPE_MIN, Grid::OCCGRID_CELLTYPE_MAX));
}

}  // namespace

BayesMapper::BayesMapper(const MapperConfig& config) : config_(config) {
  const std::string problem = config.validate();
  if (!problem.empty()) throw std::invalid_argument("mapper: " + problem);
  const auto half = static_cast<float>(config.initial_size / 2);
  grid_.setSize(-half, half, -half, half, static_cast<float>(config.resolution), 0.5f);
  // MRPT cells hold log-odds of being free: an occupied reading subtracts, a free one adds.
  logodds_hit_ = toCellLogOdds(config.model.p_occ_hit);
  logodds_pass_ = toCellLogOdds(1.0 - config.model.p_occ_pass);
}

double BayesMapper::effectiveHitProbability() const { return 1.0 - Grid::l2p(-logodds_hit_); }

double BayesMapper::effectivePassProbability() const { return 1.0 - Grid::l2p(logodds_pass_); }

wheelchair_core::OccupancyMap BayesMapper::map(const GridThresholds& thresholds) const {
  return fromMrptGrid(grid_, thresholds);
}

void BayesMapper::markFree(int ix, int iy) {
  LogOdds::updateCell_fast_free(ix, iy, logodds_pass_, Grid::OCCGRID_CELLTYPE_MAX - logodds_pass_,
                                grid_.getRow(0), grid_.getSizeX());
}

void BayesMapper::markOccupied(int ix, int iy) {
  LogOdds::updateCell_fast_occupied(ix, iy, logodds_hit_, Grid::OCCGRID_CELLTYPE_MIN + logodds_hit_,
                                    grid_.getRow(0), grid_.getSizeX());
}

// The grid grows by whole cells, so every cell keeps its place on the lattice the grid started
// on (the world's, a map's origin at a multiple of the resolution). MRPT's resizeGrid snaps a
// new border to a multiple of the resolution only when it is more than 5 % of a cell off it, and
// otherwise takes it as given: the office's live map grew to an origin 1.7 mm off its lattice
// (-16.8517 instead of -16.85), every later cell boundary 1.7 mm from the walls' faces.
void BayesMapper::growToFit(double x_min, double x_max, double y_min, double y_max) {
  const double gx_min = grid_.getXMin(), gx_max = grid_.getXMax();
  const double gy_min = grid_.getYMin(), gy_max = grid_.getYMax();
  if (x_min >= gx_min && x_max < gx_max && y_min >= gy_min && y_max < gy_max) return;
  const double res = grid_.getResolution();
  const double m = config_.growth_margin;
  // Whole cells beyond each border (none where the grid already reaches).
  auto cells = [res](double beyond) { return beyond > 0 ? std::ceil(beyond / res - 1e-6) : 0.0; };
  grid_.resizeGrid(static_cast<float>(gx_min - res * cells(gx_min - (x_min - m))),
                   static_cast<float>(gx_max + res * cells((x_max + m) - gx_max)),
                   static_cast<float>(gy_min - res * cells(gy_min - (y_min - m))),
                   static_cast<float>(gy_max + res * cells((y_max + m) - gy_max)), 0.5f, false);
}

// Cells across the beam's footprint at the return, one per half cell along the arc.
void BayesMapper::markFootprint(const wheelchair_core::Pose2D& pose, double angle, double range) {
  const double half_width = range * std::tan(config_.model.beam_width / 2);
  const double res = grid_.getResolution();
  const int steps = static_cast<int>(std::ceil(half_width / (res / 2)));
  int last_ix = -1, last_iy = -1;
  for (int k = -steps; k <= steps; ++k) {
    const double a = angle + (steps > 0 ? k * config_.model.beam_width / 2 / steps : 0.0);
    const int ix = grid_.x2idx(pose.x + range * std::cos(a));
    const int iy = grid_.y2idx(pose.y + range * std::sin(a));
    if ((ix != last_ix || iy != last_iy) && ix >= 0 && iy >= 0 &&
        ix < static_cast<int>(grid_.getSizeX()) && iy < static_cast<int>(grid_.getSizeY())) {
      markOccupied(ix, iy);
    }
    last_ix = ix;
    last_iy = iy;
  }
}

// A return's evidence goes hit_depth behind the echo (returnCellRange), within the insertion
// range; a pass-through ends where it ends.
double BayesMapper::cellRange(const BeamUse& use) const {
  if (use.kind != BeamUse::kHit) return use.length;
  return std::min(returnCellRange(use.length, config_.model.hit_depth),
                  config_.model.max_insertion_range);
}

InsertResult BayesMapper::insert(const wheelchair_core::LaserScan2D& scan,
                                 const wheelchair_core::Pose2D& pose) {
  InsertResult result;
  result.reason =
      scanInsertProblem(scan, pose, static_cast<size_t>(config_.expected_beams), last_stamp_);
  if (!result.reason.empty()) return result;
  // Beam endpoints first: the grid must contain them all before any cell is touched.
  std::vector<BeamUse> uses(scan.ranges.size());
  double x_min = pose.x, x_max = pose.x, y_min = pose.y, y_max = pose.y;
  for (size_t i = 0; i < uses.size(); ++i) {
    uses[i] = useOfBeam(scan.ranges[i], scan, config_.model);
    if (uses[i].kind == BeamUse::kSkip) continue;
    ++result.beams_used;
    const double a = pose.yaw + scan.angle_min + i * scan.angle_increment;
    const double reach = cellRange(uses[i]) * (1 + std::tan(config_.model.beam_width / 2));
    x_min = std::min(x_min, pose.x + reach * std::cos(a));
    x_max = std::max(x_max, pose.x + reach * std::cos(a));
    y_min = std::min(y_min, pose.y + reach * std::sin(a));
    y_max = std::max(y_max, pose.y + reach * std::sin(a));
  }
  if (result.beams_used == 0) {
    result.reason = "no usable beam (all NaN, -inf or out of range)";
    return result;
  }
  growToFit(x_min, x_max, y_min, y_max);
  const double res = grid_.getResolution();
  const double gx0 = (pose.x - grid_.getXMin()) / res;
  const double gy0 = (pose.y - grid_.getYMin()) / res;
  for (size_t i = 0; i < uses.size(); ++i) {
    if (uses[i].kind == BeamUse::kSkip) continue;
    const double a = pose.yaw + scan.angle_min + i * scan.angle_increment;
    const bool hit = uses[i].kind == BeamUse::kHit;
    const double length = cellRange(uses[i]);
    const double gx1 = gx0 + length * std::cos(a) / res;
    const double gy1 = gy0 + length * std::sin(a) / res;
    // One cell per cell of travel (8-connected): the cells a beam only clips at a corner are
    // left alone. Freeing them as well (every crossed cell, 4-connected) erased the corners of
    // walls that beams pass at a grazing angle: on real logs the echoes at the corrected poses
    // fitted the map at 0.959 instead of 0.973 (Intel, p_occ_hit 0.7).
    wheelchair_core::traceLineCells(
        static_cast<int>(std::floor(gx0)), static_cast<int>(std::floor(gy0)),
        static_cast<int>(std::floor(gx1)), static_cast<int>(std::floor(gy1)),
        [&](int ix, int iy, bool last) {
          if (!(hit && last)) markFree(ix, iy);
        });
    if (hit && config_.model.beam_width > 0) {
      markFootprint(pose, a, length);
    } else if (hit) {
      markOccupied(static_cast<int>(std::floor(gx1)), static_cast<int>(std::floor(gy1)));
    }
  }
  last_stamp_ = scan.stamp;
  ++scans_inserted_;
  result.inserted = true;
  return result;
}

}  // namespace wheelchair_mapping
