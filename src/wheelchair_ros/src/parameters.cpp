#include <ros/ros.h>
#include <wheelchair_ros/parameters.h>
#include <xmlrpcpp/XmlRpcValue.h>

namespace wheelchair_ros {

using wheelchair_core::ConfigError;

RosParameterSource::RosParameterSource(const ros::NodeHandle& nh) : nh_(nh) {}

std::vector<std::string> RosParameterSource::keys() const {
  std::vector<std::string> all, mine;
  nh_.getParamNames(all);
  const std::string prefix = nh_.getNamespace() + "/";
  for (const std::string& name : all)
    if (name.compare(0, prefix.size(), prefix) == 0) mine.push_back(name.substr(prefix.size()));
  return mine;
}

namespace {

using Type = XmlRpc::XmlRpcValue::Type;

[[noreturn]] void wrongType(const ros::NodeHandle& nh, const std::string& key, const char* type) {
  throw ConfigError(nh.getNamespace() + ": parameter '" + key + "' must be " + type);
}

bool fetch(const ros::NodeHandle& nh, const std::string& key, XmlRpc::XmlRpcValue& v) {
  return nh.hasParam(key) && nh.getParam(key, v);
}

bool asNumber(XmlRpc::XmlRpcValue& v, double& out) {
  if (v.getType() == Type::TypeDouble) {
    out = static_cast<double>(v);
    return true;
  }
  if (v.getType() == Type::TypeInt) {
    out = static_cast<int>(v);
    return true;
  }
  return false;
}

}  // namespace

bool RosParameterSource::get(const std::string& key, bool& value) const {
  XmlRpc::XmlRpcValue v;
  if (!fetch(nh_, key, v)) return false;
  if (v.getType() != Type::TypeBoolean) wrongType(nh_, key, "true or false");
  value = static_cast<bool>(v);
  return true;
}

bool RosParameterSource::get(const std::string& key, int& value) const {
  XmlRpc::XmlRpcValue v;
  if (!fetch(nh_, key, v)) return false;
  if (v.getType() != Type::TypeInt) wrongType(nh_, key, "an integer");
  value = static_cast<int>(v);
  return true;
}

bool RosParameterSource::get(const std::string& key, double& value) const {
  XmlRpc::XmlRpcValue v;
  if (!fetch(nh_, key, v)) return false;
  if (!asNumber(v, value)) wrongType(nh_, key, "a number");
  return true;
}

bool RosParameterSource::get(const std::string& key, std::string& value) const {
  XmlRpc::XmlRpcValue v;
  if (!fetch(nh_, key, v)) return false;
  if (v.getType() != Type::TypeString) wrongType(nh_, key, "a string");
  value = static_cast<std::string>(v);
  return true;
}

bool RosParameterSource::get(const std::string& key, std::vector<double>& value) const {
  XmlRpc::XmlRpcValue v;
  if (!fetch(nh_, key, v)) return false;
  if (v.getType() != Type::TypeArray) wrongType(nh_, key, "a list of numbers");
  std::vector<double> out(v.size());
  for (int i = 0; i < v.size(); ++i)
    if (!asNumber(v[i], out[i])) wrongType(nh_, key, "a list of numbers");
  value = out;
  return true;
}

bool RosParameterSource::get(const std::string& key, std::vector<std::string>& value) const {
  XmlRpc::XmlRpcValue v;
  if (!fetch(nh_, key, v)) return false;
  if (v.getType() != Type::TypeArray) wrongType(nh_, key, "a list of strings");
  std::vector<std::string> out;
  for (int i = 0; i < v.size(); ++i) {
    if (v[i].getType() != Type::TypeString) wrongType(nh_, key, "a list of strings");
    out.push_back(static_cast<std::string>(v[i]));
  }
  value = out;
  return true;
}

bool RosParameterSource::get(const std::string& key, std::vector<Eigen::Vector2d>& value) const {
  XmlRpc::XmlRpcValue v;
  if (!fetch(nh_, key, v)) return false;
  if (v.getType() != Type::TypeArray) wrongType(nh_, key, "a list of [x, y] pairs");
  std::vector<Eigen::Vector2d> out;
  for (int i = 0; i < v.size(); ++i) {
    Eigen::Vector2d p;
    if (v[i].getType() != Type::TypeArray || v[i].size() != 2 || !asNumber(v[i][0], p.x()) ||
        !asNumber(v[i][1], p.y()))
      wrongType(nh_, key, "a list of [x, y] pairs");
    out.push_back(p);
  }
  value = out;
  return true;
}

}  // namespace wheelchair_ros
