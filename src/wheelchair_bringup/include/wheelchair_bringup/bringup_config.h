// The chair's bring-up file: which nodelets one process loads, with their parameters and
// remappings. Read without ROS; turned into parameters and nodelet loads by chair_main.
#pragma once

#include <yaml-cpp/yaml.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace wheelchair_bringup {

struct NodeletSpec {
  std::string name;                           ///< node name, e.g. "localizer"
  std::string type;                           ///< e.g. "wheelchair_kld/KldLocalizerNodelet"
  YAML::Node params;                          ///< its private parameters (a map, may be null)
  std::map<std::string, std::string> remaps;  ///< topic remappings, from -> to
};

struct BringupConfig {
  YAML::Node global_params;  ///< set at the root of the parameter server (e.g. use_sim_time)
  /// Threads of the nodelet manager: every nodelet's callbacks run on one of them at a time, so
  /// a slow callback (a scan update, a plan) must not starve the base driver's timer.
  int num_worker_threads = 8;
  std::vector<NodeletSpec> nodelets;
};

/// Resolves "$(find pkg)" in a string with `find` (returns the package path or "").
using PackageFinder = std::function<std::string(const std::string&)>;
std::string substitute(const std::string& text, const PackageFinder& find);

/// Reads `num_worker_threads: N` (optional, >= 1), `params: {...}` and `nodelets: [{name, type,
/// params, remap}, ...]`; every string scalar has "$(find pkg)" resolved. Throws std::runtime_error
/// naming the file and problem.
BringupConfig loadBringupConfig(const std::string& path, const PackageFinder& find);

}  // namespace wheelchair_bringup
