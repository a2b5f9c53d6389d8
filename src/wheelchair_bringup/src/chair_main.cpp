// `rosrun wheelchair_bringup wheelchair [config.yaml]`: the whole chair in one process.
// One nodelet manager loads the map server, localizer, planner host, controller, base driver,
// supervisor and rider interface listed in the bring-up file, each with its parameters, so
// messages pass between them as shared pointers (no copies, no serialization). It refuses to
// start (exit 1, one line saying why) on a bad bring-up file, an override for a nodelet the file
// does not list, a missing file a nodelet reads (*_file), or a nodelet that refuses to load
// (an unknown or invalid parameter).
// ~callback_cpu (std_msgs/String, latched, every second): the CPU seconds each nodelet's
// callbacks took so far, as JSON {"wall_time": <s>, "/controller": 1.234, ...}
// (wheelchair_core/callback_cpu.h; the manager's threads are shared, so /proc cannot tell the
// nodelets apart); bench/system turns two of them into % of one core per nodelet.
#include <wheelchair_bringup/bringup_config.h>
#include <wheelchair_core/callback_cpu.h>

#include <nodelet/loader.h>
#include <ros/package.h>
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <set>

namespace {

/// yaml-cpp node -> XmlRpc value for the parameter server (ints, doubles, bools, strings,
/// lists, maps).
XmlRpc::XmlRpcValue toXmlRpc(const YAML::Node& node) {
  if (node.IsSequence()) {
    XmlRpc::XmlRpcValue list;
    list.setSize(static_cast<int>(node.size()));
    for (size_t i = 0; i < node.size(); ++i) list[static_cast<int>(i)] = toXmlRpc(node[i]);
    return list;
  }
  if (node.IsMap()) {
    XmlRpc::XmlRpcValue map;
    for (const auto& item : node) map[item.first.as<std::string>()] = toXmlRpc(item.second);
    return map;
  }
  const std::string text = node.Scalar();
  if (node.Tag() != "!") {  // unquoted scalars may be numbers or booleans
    int integer;
    double real;
    bool flag;
    if (YAML::convert<int>::decode(node, integer) && text.find('.') == std::string::npos)
      return XmlRpc::XmlRpcValue(integer);
    if (YAML::convert<double>::decode(node, real)) return XmlRpc::XmlRpcValue(real);
    if (YAML::convert<bool>::decode(node, flag)) return XmlRpc::XmlRpcValue(flag);
  }
  return XmlRpc::XmlRpcValue(text);
}

void setParams(const std::string& ns, const YAML::Node& params) {
  if (!params || !params.IsMap()) return;
  for (const auto& item : params)
    ros::param::set(ns + "/" + item.first.as<std::string>(), toXmlRpc(item.second));
}

/// Empty if every private parameter of the `wheelchair` node is ~num_worker_threads or an
/// override ~<nodelet>/<key> of a nodelet of the file; else the first that is neither.
std::string unknownOverride(const wheelchair_bringup::BringupConfig& config) {
  std::set<std::string> known{"num_worker_threads"};
  for (const auto& spec : config.nodelets) known.insert(spec.name);
  std::vector<std::string> names;
  ros::param::getParamNames(names);
  const std::string prefix = ros::this_node::getName() + "/";
  for (const std::string& name : names) {
    if (name.rfind(prefix, 0) != 0) continue;
    const std::string key = name.substr(prefix.size());
    if (!known.count(key.substr(0, key.find('/')))) return "~" + key;
  }
  return "";
}

/// The per-run overrides ~<nodelet>/<key> of one nodelet that are strings (file paths among
/// them), for the file check before anything is set.
std::map<std::string, std::string> stringOverrides(const std::string& nodelet) {
  std::map<std::string, std::string> out;
  XmlRpc::XmlRpcValue overrides;
  if (!ros::param::get("~" + nodelet, overrides) ||
      overrides.getType() != XmlRpc::XmlRpcValue::TypeStruct)
    return out;
  for (auto& item : overrides)
    out[item.first] = item.second.getType() == XmlRpc::XmlRpcValue::TypeString
                          ? static_cast<std::string>(item.second)
                          : std::string();
  return out;
}

/// Per-run overrides: the `wheelchair` node's private parameters ~<nodelet>/<key> (e.g.
/// `_base_driver/udp_local_port:=47120`, or <param> inside a rostest's <node>) win over the file.
void overlayPrivateParams(const std::string& nodelet, const std::string& ns) {
  XmlRpc::XmlRpcValue overrides;
  if (!ros::param::get("~" + nodelet, overrides) ||
      overrides.getType() != XmlRpc::XmlRpcValue::TypeStruct)
    return;
  for (auto& item : overrides) {
    ros::param::set(ns + "/" + item.first, item.second);
    ROS_INFO("%s/%s overridden on the command line", ns.c_str(), item.first.c_str());
  }
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "wheelchair");
  std::vector<std::string> args;
  ros::removeROSArgs(argc, argv, args);
  const std::string config_dir = ros::package::getPath("wheelchair_bringup") + "/config/";
  std::string config_path = args.size() > 1 ? args[1] : config_dir + "chair_sim.yaml";
  // A bare name that is not a file here is one of this package's (`wheelchair mapping.yaml`).
  if (config_path.find('/') == std::string::npos && !std::ifstream(config_path))
    config_path = config_dir + config_path;
  wheelchair_bringup::BringupConfig config;
  try {
    config = wheelchair_bringup::loadBringupConfig(config_path, &ros::package::getPath);
  } catch (const std::exception& e) {
    ROS_FATAL("%s", e.what());
    return 1;
  }
  const std::string unknown = unknownOverride(config);
  if (!unknown.empty()) {
    ROS_FATAL("%s: override %s names no nodelet of the file", config_path.c_str(), unknown.c_str());
    return 1;
  }
  for (const auto& spec : config.nodelets) {  // before anything is set: a refusal changes nothing
    const std::string missing = wheelchair_bringup::missingFile(spec, stringOverrides(spec.name));
    if (!missing.empty()) {
      ROS_FATAL("%s: %s (a file the chair needs: see wheelchair_bringup/README.md)",
                config_path.c_str(), missing.c_str());
      return 1;
    }
  }
  setParams("", config.global_params);
  if (!ros::param::has("~num_worker_threads"))  // read by the manager; a run may override it
    ros::param::set("~num_worker_threads", config.num_worker_threads);
  nodelet::Loader loader(true);  // a manager others could also load into
  const nodelet::V_string no_argv;
  for (const auto& spec : config.nodelets) {
    const std::string name = ros::names::resolve(spec.name);
    setParams(name, spec.params);
    overlayPrivateParams(spec.name, name);
    nodelet::M_string remaps;
    for (const auto& [from, to] : spec.remaps)
      remaps[ros::names::resolve(from)] = ros::names::resolve(to);
    if (!loader.load(name, spec.type, remaps, no_argv)) {
      ROS_FATAL("%s: could not load nodelet %s (%s)", config_path.c_str(), name.c_str(),
                spec.type.c_str());
      return 1;
    }
    ROS_INFO("loaded %s (%s)", name.c_str(), spec.type.c_str());
  }
  ros::NodeHandle pnh("~");
  ros::Publisher cpu_pub = pnh.advertise<std_msgs::String>("callback_cpu", 1, true);
  const ros::WallTimer cpu_timer =
      pnh.createWallTimer(ros::WallDuration(1.0), [&cpu_pub](const ros::WallTimerEvent&) {
        std_msgs::String msg;
        char item[160];
        std::snprintf(item, sizeof(item), "{\"wall_time\": %.6f", ros::WallTime::now().toSec());
        msg.data = item;
        for (const auto& [nodelet, seconds] : wheelchair_core::callbackCpuSeconds()) {
          std::snprintf(item, sizeof(item), ", \"%s\": %.6f", nodelet.c_str(), seconds);
          msg.data += item;
        }
        msg.data += "}";
        cpu_pub.publish(msg);
      });
  ros::spin();
  return 0;
}
