#include <wheelchair_bringup/bringup_config.h>

#include <fstream>
#include <set>
#include <stdexcept>

namespace wheelchair_bringup {
namespace {

/// A deep copy of `node` with "$(find pkg)" resolved in every string scalar.
YAML::Node resolved(const YAML::Node& node, const PackageFinder& find) {
  if (node.IsScalar()) {
    const std::string text = node.Scalar();
    return text.find("$(find ") == std::string::npos ? YAML::Clone(node)
                                                     : YAML::Node(substitute(text, find));
  }
  YAML::Node out = YAML::Clone(node);
  if (node.IsMap())
    for (const auto& item : node) out[item.first.as<std::string>()] = resolved(item.second, find);
  if (node.IsSequence())
    for (size_t i = 0; i < node.size(); ++i) out[i] = resolved(node[i], find);
  return out;
}

}  // namespace

std::string substitute(const std::string& text, const PackageFinder& find) {
  std::string out = text;
  for (size_t at = out.find("$(find "); at != std::string::npos; at = out.find("$(find ", at)) {
    const size_t end = out.find(')', at);
    if (end == std::string::npos)
      throw std::runtime_error("unclosed $(find ...) in '" + text + "'");
    const std::string package = out.substr(at + 7, end - at - 7);
    const std::string path = find(package);
    if (path.empty()) throw std::runtime_error("package '" + package + "' not found");
    out.replace(at, end - at + 1, path);
    at += path.size();
  }
  return out;
}

BringupConfig loadBringupConfig(const std::string& path, const PackageFinder& find) {
  if (!std::ifstream(path)) throw std::runtime_error(path + ": cannot open bring-up file");
  BringupConfig config;
  try {
    const YAML::Node root = YAML::LoadFile(path);
    config.global_params = resolved(root["params"] ? root["params"] : YAML::Node(), find);
    if (root["num_worker_threads"]) {
      config.num_worker_threads = root["num_worker_threads"].as<int>();
      if (config.num_worker_threads < 1)
        throw std::runtime_error("num_worker_threads must be >= 1");
    }
    const YAML::Node list = root["nodelets"];
    if (!list || !list.IsSequence() || list.size() == 0)
      throw std::runtime_error("no 'nodelets' list");
    std::set<std::string> names;
    for (const auto& entry : list) {
      NodeletSpec spec;
      if (!entry["name"] || !entry["type"]) throw std::runtime_error("a nodelet without name/type");
      spec.name = entry["name"].as<std::string>();
      spec.type = entry["type"].as<std::string>();
      if (!names.insert(spec.name).second)
        throw std::runtime_error("nodelet name '" + spec.name + "' used twice");
      spec.params = resolved(entry["params"] ? entry["params"] : YAML::Node(), find);
      if (entry["remap"])
        for (const auto& item : entry["remap"])
          spec.remaps[item.first.as<std::string>()] = item.second.as<std::string>();
      config.nodelets.push_back(spec);
    }
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(path + ": bad YAML: " + e.what());
  } catch (const std::runtime_error& e) {
    if (std::string(e.what()).rfind(path, 0) == 0) throw;
    throw std::runtime_error(path + ": " + e.what());
  }
  return config;
}

}  // namespace wheelchair_bringup
