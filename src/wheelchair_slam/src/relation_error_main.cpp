// rosrun wheelchair_slam relation_error --trajectory T.csv (--relations FILE | --reference R.csv
//   [--all-pairs]) [--offset S] [--tolerance S]
// The Kuemmerle relation error of a trajectory (CSV stamp,x,y,yaw) as one JSON object: against a
// .relations file (relation time = trajectory time + offset), or against consecutive poses (or
// every pair of poses) of a reference trajectory.
#include <wheelchair_logs/relations.h>
#include <wheelchair_slam/trajectory_io.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

namespace {

const char* kUsage =
    "usage: relation_error --trajectory T.csv (--relations FILE | --reference R.csv "
    "[--all-pairs])\n"
    "                      [--offset S] [--tolerance S]\n";

void printSummary(const char* name, const wheelchair_logs::ErrorSummary& s, double scale) {
  std::printf("\"%s\": {\"mean\": %.6f, \"std\": %.6f, \"max\": %.6f}", name, s.mean * scale,
              s.std * scale, s.max * scale);
}

}  // namespace

int main(int argc, char** argv) {
  std::string trajectory, relations, reference;
  double offset = 0.0, tolerance = 1e-4;
  bool all_pairs = false;
  for (int i = 1; i < argc; ++i) {
    const std::string k = argv[i];
    if (k == "--all-pairs") {
      all_pairs = true;
      continue;
    }
    if (i + 1 >= argc) {
      std::cerr << kUsage;
      return 2;
    }
    const std::string v = argv[++i];
    if (k == "--trajectory")
      trajectory = v;
    else if (k == "--relations")
      relations = v;
    else if (k == "--reference")
      reference = v;
    else if (k == "--offset")
      offset = std::atof(v.c_str());
    else if (k == "--tolerance")
      tolerance = std::atof(v.c_str());
    else {
      std::cerr << "relation_error: unknown argument '" << k << "'\n" << kUsage;
      return 2;
    }
  }
  if (trajectory.empty() || relations.empty() == reference.empty()) {
    std::cerr << kUsage;
    return 2;
  }
  try {
    const auto poses = wheelchair_slam::readTrajectoryCsv(trajectory);
    const auto rel = relations.empty()
                         ? wheelchair_logs::referenceRelations(
                               wheelchair_slam::readTrajectoryCsv(reference), all_pairs)
                         : wheelchair_logs::readRelations(relations);
    const auto errors = wheelchair_logs::relationErrors(rel, poses, offset, tolerance);
    std::printf("{\"relations\": %zu, \"matched\": %zu, ", errors.relations,
                errors.translational.size());
    printSummary("translational_m", wheelchair_logs::summarize(errors.translational), 1.0);
    std::printf(", ");
    printSummary("rotational_deg", wheelchair_logs::summarize(errors.rotational), 180.0 / M_PI);
    std::printf("}\n");
  } catch (const std::exception& e) {
    std::cerr << "relation_error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
