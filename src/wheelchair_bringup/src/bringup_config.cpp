#include <wheelchair_bringup/bringup_config.h>
#include <wheelchair_core/config.h>

#include <cstdlib>
#include <fstream>
#include <set>
#include <stdexcept>

namespace wheelchair_bringup {
namespace {

/// A deep copy of `node` with "$(find pkg)" and "$(env VAR)" resolved in every string scalar.
YAML::Node resolved(const YAML::Node& node, const PackageFinder& find) {
  if (node.IsScalar()) {
    const std::string text = node.Scalar();
    return text.find("$(") == std::string::npos ? YAML::Clone(node)
                                                : YAML::Node(substitute(text, find));
  }
  YAML::Node out = YAML::Clone(node);
  if (node.IsMap())
    for (const auto& item : node) out[item.first.as<std::string>()] = resolved(item.second, find);
  if (node.IsSequence())
    for (size_t i = 0; i < node.size(); ++i) out[i] = resolved(node[i], find);
  return out;
}

/// Throws if the mapping `node` has a key not in `known`: a misspelt key is an error, not a
/// silently ignored setting.
void refuseUnknownKeys(const YAML::Node& node, const std::set<std::string>& known,
                       const std::string& where) {
  if (!node.IsMap()) throw std::runtime_error(where + " must be a mapping");
  for (const auto& item : node) {
    const std::string key = item.first.as<std::string>();
    if (known.count(key)) continue;
    std::string list;
    for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
    throw std::runtime_error(where + ": unknown key '" + key + "' (known: " + list + ")");
  }
}

std::string resolveOne(const std::string& kind, const std::string& argument,
                       const PackageFinder& find) {
  if (kind == "find") {
    const std::string path = find(argument);
    if (path.empty()) throw std::runtime_error("package '" + argument + "' not found");
    return path;
  }
  if (kind == "env") {
    const char* value = std::getenv(argument.c_str());
    if (value == nullptr)
      throw std::runtime_error("environment variable '" + argument + "' is not set");
    return value;
  }
  throw std::runtime_error("unknown substitution '$(" + kind + " ...)' (known: find, env)");
}

}  // namespace

std::string BringupConfig::validate() const {
  wheelchair_core::ConfigChecks checks;
  checks
      .check(num_worker_threads >= 1,
             "num_worker_threads must be >= 1 (got " + std::to_string(num_worker_threads) + ")")
      .check(!nodelets.empty(), "no 'nodelets' list");
  return checks.result();
}

std::string substitute(const std::string& text, const PackageFinder& find) {
  std::string out = text;
  for (size_t at = out.find("$("); at != std::string::npos; at = out.find("$(", at)) {
    const size_t end = out.find(')', at);
    if (end == std::string::npos) throw std::runtime_error("unclosed $(...) in '" + text + "'");
    const std::string inner = out.substr(at + 2, end - at - 2);
    const size_t space = inner.find(' ');
    const std::string value =
        resolveOne(inner.substr(0, space),
                   space == std::string::npos ? std::string() : inner.substr(space + 1), find);
    out.replace(at, end - at + 1, value);
    at += value.size();
  }
  return out;
}

BringupConfig loadBringupConfig(const std::string& path, const PackageFinder& find) {
  if (!std::ifstream(path)) throw std::runtime_error(path + ": cannot open bring-up file");
  BringupConfig config;
  try {
    const YAML::Node root = YAML::LoadFile(path);
    refuseUnknownKeys(root, {"num_worker_threads", "params", "nodelets"}, "the bring-up file");
    config.global_params = resolved(root["params"] ? root["params"] : YAML::Node(), find);
    if (root["num_worker_threads"])
      config.num_worker_threads = root["num_worker_threads"].as<int>();
    const YAML::Node list =
        root["nodelets"] ? root["nodelets"] : YAML::Node(YAML::NodeType::Sequence);
    if (!list.IsSequence()) throw std::runtime_error("'nodelets' must be a list");
    std::set<std::string> names;
    for (const auto& entry : list) {
      NodeletSpec spec;
      if (!entry.IsMap() || !entry["name"] || !entry["type"])
        throw std::runtime_error("a nodelet without name/type");
      spec.name = entry["name"].as<std::string>();
      spec.type = entry["type"].as<std::string>();
      refuseUnknownKeys(entry, {"name", "type", "params", "remap"}, "nodelet '" + spec.name + "'");
      if (!names.insert(spec.name).second)
        throw std::runtime_error("nodelet name '" + spec.name + "' used twice");
      spec.params = resolved(entry["params"] ? entry["params"] : YAML::Node(), find);
      if (entry["remap"])
        for (const auto& item : entry["remap"])
          spec.remaps[item.first.as<std::string>()] = item.second.as<std::string>();
      config.nodelets.push_back(spec);
    }
    const std::string problem = config.validate();
    if (!problem.empty()) throw std::runtime_error(problem);
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(path + ": bad YAML: " + e.what());
  } catch (const std::runtime_error& e) {
    if (std::string(e.what()).rfind(path, 0) == 0) throw;
    throw std::runtime_error(path + ": " + e.what());
  }
  return config;
}

bool isFileParameter(const std::string& key) {
  const std::string suffix = "_file";
  return key.size() > suffix.size() &&
         key.compare(key.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string missingFile(const NodeletSpec& spec,
                        const std::map<std::string, std::string>& overrides) {
  std::map<std::string, std::string> files;
  if (spec.params && spec.params.IsMap())
    for (const auto& item : spec.params) {
      const std::string key = item.first.as<std::string>();
      if (isFileParameter(key)) files[key] = item.second.IsScalar() ? item.second.Scalar() : "";
    }
  for (const auto& [key, path] : overrides)
    if (isFileParameter(key)) files[key] = path;
  for (const auto& [key, path] : files)
    if (!std::ifstream(path)) return "/" + spec.name + "/" + key + ": cannot read '" + path + "'";
  return "";
}

}  // namespace wheelchair_bringup
