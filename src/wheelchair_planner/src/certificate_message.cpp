#include "certificate_message.h"

namespace wheelchair_planner {

wheelchair_msgs::PlanCertificate toPlanCertificateMsg(const Certificate& c,
                                                      const std_msgs::Header& header) {
  wheelchair_msgs::PlanCertificate m;
  m.header = header;
  m.success = c.success;
  m.planner = c.planner;
  m.failure_reason = c.failure_reason;
  m.solver_iterations = c.solver_iterations;
  m.solver_residual = c.solver_residual;
  m.solver_converged = c.solver_converged;
  m.warm_started = c.warm_started;
  m.descent_reached_goal = c.descent_reached_goal;
  m.plateau_steps = c.plateau_steps;
  m.min_gradient = c.min_gradient;
  m.length = c.length;
  m.max_curvature = c.max_curvature;
  m.min_clearance = c.min_clearance;
  m.min_clearance_point.x = c.min_clearance_x;
  m.min_clearance_point.y = c.min_clearance_y;
  m.clearance.assign(c.clearance.begin(), c.clearance.end());
  m.planning_time = c.planning_time;
  m.path_stage = c.path_stage;
  m.footprint_checked = c.footprint_checked;
  m.footprint_clearance = c.footprint_clearance;
  m.footprint_clearance_point.x = c.footprint_clearance_x;
  m.footprint_clearance_point.y = c.footprint_clearance_y;
  m.sweep_poses = c.sweep_poses;
  m.first_stage_sweep = c.first_stage_sweep;
  m.search_expansions = c.search_expansions;
  m.search_time = c.search_time;
  m.cusps = c.cusps;
  m.reversed_length = c.reversed_length;
  m.segment_reverse.assign(c.segment_reverse.begin(), c.segment_reverse.end());
  m.segment_clearance.assign(c.segment_clearance.begin(), c.segment_clearance.end());
  return m;
}

}  // namespace wheelchair_planner
