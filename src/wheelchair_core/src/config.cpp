#include <wheelchair_core/config.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <iomanip>

namespace wheelchair_core {

void ConfigReader::renamed(const std::string& old_key, const std::string& new_key) const {
  for (const std::string& key : source_.keys()) {
    if (key == old_key)
      throw ConfigError(source_.where() + ": parameter '" + old_key + "' is now called '" +
                        new_key + "'");
  }
}

void ConfigReader::rejectUnknown() const {
  for (const std::string& key : source_.keys()) {
    if (known_.count(key)) continue;
    std::string list;
    for (const std::string& k : known_) list += (list.empty() ? "" : ", ") + k;
    throw ConfigError(source_.where() + ": unknown parameter '" + key + "' (known: " + list + ")");
  }
}

namespace {

std::string number(double value) {
  std::ostringstream os;
  os << std::setprecision(6) << value;
  return os.str();
}

}  // namespace

ConfigChecks& ConfigChecks::positive(const char* name, double value) {
  return check(std::isfinite(value) && value > 0.0,
               std::string(name) + " must be positive (got " + number(value) + ")");
}

ConfigChecks& ConfigChecks::nonNegative(const char* name, double value) {
  return check(std::isfinite(value) && value >= 0.0,
               std::string(name) + " must not be negative (got " + number(value) + ")");
}

ConfigChecks& ConfigChecks::finite(const char* name, double value) {
  return check(std::isfinite(value),
               std::string(name) + " must be finite (got " + number(value) + ")");
}

ConfigChecks& ConfigChecks::inRange(const char* name, double value, double lo, double hi) {
  return check(value >= lo && value <= hi, std::string(name) + " must lie in [" + number(lo) +
                                               ", " + number(hi) + "] (got " + number(value) + ")");
}

std::string ConfigChecks::result() const {
  std::string all;
  for (const std::string& p : problems_) all += (all.empty() ? "" : "; ") + p;
  return all;
}

struct YamlParameterSource::Impl {
  YAML::Node root;

  /// The node at "a/b/c", or an undefined node.
  YAML::Node find(const std::string& key) const {
    YAML::Node node = root;
    size_t start = 0;
    while (node.IsMap()) {
      const size_t slash = key.find('/', start);
      const std::string part =
          key.substr(start, slash == std::string::npos ? std::string::npos : slash - start);
      const YAML::Node& lookup = node;  // const: operator[] must not insert the key
      YAML::Node child = lookup[part];
      if (!child || slash == std::string::npos) return child;
      node.reset(child);
      start = slash + 1;
    }
    return YAML::Node(YAML::NodeType::Undefined);
  }

  void collect(const YAML::Node& node, const std::string& prefix,
               std::vector<std::string>& out) const {
    for (const auto& item : node) {
      const std::string key = prefix + item.first.as<std::string>();
      if (item.second.IsMap())
        collect(item.second, key + "/", out);
      else
        out.push_back(key);
    }
  }
};

YamlParameterSource::YamlParameterSource(const YAML::Node& node, std::string where)
    : impl_(std::make_unique<Impl>()), where_(std::move(where)) {
  if (node && !node.IsNull() && !node.IsMap())
    throw ConfigError(where_ + ": expected a mapping of parameters");
  impl_->root = node ? node : YAML::Node(YAML::NodeType::Map);
}

YamlParameterSource::~YamlParameterSource() = default;
YamlParameterSource::YamlParameterSource(YamlParameterSource&&) noexcept = default;

YamlParameterSource YamlParameterSource::fromFile(const std::string& path) {
  YAML::Node node;
  try {
    node = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw ConfigError(path + ": cannot read parameters: " + e.what());
  }
  return YamlParameterSource(node, path);
}

std::vector<std::string> YamlParameterSource::keys() const {
  std::vector<std::string> out;
  if (impl_->root.IsMap()) impl_->collect(impl_->root, "", out);
  return out;
}

namespace {

template <typename T>
bool getScalar(const YAML::Node& node, const std::string& where, const std::string& key,
               const char* type, T& value) {
  if (!node || node.IsNull()) return false;
  try {
    if (!node.IsScalar()) throw YAML::Exception(YAML::Mark::null_mark(), "not a scalar");
    value = node.as<T>();
  } catch (const YAML::Exception&) {
    throw ConfigError(where + ": parameter '" + key + "' must be " + type);
  }
  return true;
}

template <typename T>
bool getList(const YAML::Node& node, const std::string& where, const std::string& key,
             const char* type, std::vector<T>& value) {
  if (!node || node.IsNull()) return false;
  try {
    if (!node.IsSequence()) throw YAML::Exception(YAML::Mark::null_mark(), "not a list");
    std::vector<T> out;
    for (const auto& item : node) out.push_back(item.as<T>());
    value = out;
  } catch (const YAML::Exception&) {
    throw ConfigError(where + ": parameter '" + key + "' must be " + type);
  }
  return true;
}

}  // namespace

bool YamlParameterSource::get(const std::string& key, bool& value) const {
  return getScalar(impl_->find(key), where_, key, "true or false", value);
}
bool YamlParameterSource::get(const std::string& key, int& value) const {
  return getScalar(impl_->find(key), where_, key, "an integer", value);
}
bool YamlParameterSource::get(const std::string& key, double& value) const {
  return getScalar(impl_->find(key), where_, key, "a number", value);
}
bool YamlParameterSource::get(const std::string& key, std::string& value) const {
  return getScalar(impl_->find(key), where_, key, "a string", value);
}
bool YamlParameterSource::get(const std::string& key, std::vector<double>& value) const {
  return getList(impl_->find(key), where_, key, "a list of numbers", value);
}
bool YamlParameterSource::get(const std::string& key, std::vector<std::string>& value) const {
  return getList(impl_->find(key), where_, key, "a list of strings", value);
}
bool YamlParameterSource::get(const std::string& key, std::vector<Eigen::Vector2d>& value) const {
  const YAML::Node node = impl_->find(key);
  if (!node || node.IsNull()) return false;
  // The message names the item that is wrong ("'footprint[2][1]' is not a number").
  const auto wrong = [&](const std::string& item, const char* what) {
    return ConfigError(where_ + ": parameter '" + key + "' must be a list of [x, y] pairs ('" +
                       key + item + "' " + what + ")");
  };
  if (!node.IsSequence()) throw wrong("", "is not a list");
  std::vector<Eigen::Vector2d> points;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const YAML::Node pair = node[i];
    const std::string item = "[" + std::to_string(i) + "]";
    if (!pair.IsSequence() || pair.size() != 2) throw wrong(item, "is not an [x, y] pair");
    Eigen::Vector2d p;
    for (int c = 0; c < 2; ++c) {
      try {
        if (!pair[c].IsScalar()) throw YAML::Exception(YAML::Mark::null_mark(), "not a scalar");
        p[c] = pair[c].as<double>();
      } catch (const YAML::Exception&) {
        throw wrong(item + "[" + std::to_string(c) + "]", "is not a number");
      }
    }
    points.push_back(p);
  }
  value = points;
  return true;
}

}  // namespace wheelchair_core
