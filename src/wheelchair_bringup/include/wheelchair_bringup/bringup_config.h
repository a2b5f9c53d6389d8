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

  /// "" if usable, else every problem.
  std::string validate() const;
};

/// Resolves "$(find pkg)" in a string with `find` (returns the package path or "") and
/// "$(env VAR)" with the process's environment (an unset variable is an error, as in roslaunch).
using PackageFinder = std::function<std::string(const std::string&)>;
std::string substitute(const std::string& text, const PackageFinder& find);

/// Reads `num_worker_threads: N` (optional, >= 1), `params: {...}` and `nodelets: [{name, type,
/// params, remap}, ...]`; every string scalar has "$(find pkg)" and "$(env VAR)" resolved. Any
/// other key, at the top or in a nodelet, is refused. Throws std::runtime_error naming the file
/// and the problem.
BringupConfig loadBringupConfig(const std::string& path, const PackageFinder& find);

/// A nodelet parameter whose name ends in "_file" names a file the nodelet reads (chair_file,
/// map_file, places_file): the chair does not start when one is missing.
bool isFileParameter(const std::string& key);

/// The first file parameter of `spec` (its params, with `overrides` by key winning) that names a
/// file that cannot be read, as "/<nodelet>/<key>: cannot read '<path>'"; "" if there is none.
std::string missingFile(const NodeletSpec& spec,
                        const std::map<std::string, std::string>& overrides = {});

}  // namespace wheelchair_bringup
