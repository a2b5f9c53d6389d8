// The one parameter pattern of the project (cartographer_ros's "one options dictionary that
// fails fast"): every configuration struct has its defaults in its declaration and a
// `validate()` that says what is wrong; a reader function names every key it takes; the loader
// reads them from a ParameterSource (ROS private parameters, a YAML file), refuses a key that
// nobody reads (a misspelt key is an error, not a silent default) and an old key that was
// renamed (naming the new one), then validates. Nothing here depends on ROS.
#pragma once

#include <Eigen/Core>

#include <memory>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace YAML {
class Node;
}

namespace wheelchair_core {

/// A configuration that cannot be used; what() names where, which key and what is wrong.
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Typed values by key. Nested maps are flattened with '/' ("search/time_budget").
class ParameterSource {
 public:
  virtual ~ParameterSource() = default;
  /// Every key the source holds.
  virtual std::vector<std::string> keys() const = 0;
  /// Each get() reads `key` into `value` and returns true if present, false if absent; it
  /// throws ConfigError if the value has another type (an int is accepted for a double).
  virtual bool get(const std::string& key, bool& value) const = 0;
  virtual bool get(const std::string& key, int& value) const = 0;
  virtual bool get(const std::string& key, double& value) const = 0;
  virtual bool get(const std::string& key, std::string& value) const = 0;
  virtual bool get(const std::string& key, std::vector<double>& value) const = 0;
  virtual bool get(const std::string& key, std::vector<std::string>& value) const = 0;
  /// A list of [x, y] pairs, e.g. a polygon.
  virtual bool get(const std::string& key, std::vector<Eigen::Vector2d>& value) const = 0;
  /// Where the values come from, for messages ("/localizer", "chair.yaml").
  virtual std::string where() const = 0;
};

/// Reads keys from a source and remembers which keys are known.
class ConfigReader {
 public:
  explicit ConfigReader(const ParameterSource& source) : source_(source) {}

  /// Reads `key` into `field` if the source has it; otherwise the field keeps its default.
  template <typename T>
  void read(const std::string& key, T& field) {
    known_.insert(key);
    source_.get(key, field);
  }
  /// Reads `key` into `field`; throws ConfigError if the source does not have it.
  template <typename T>
  void require(const std::string& key, T& field) {
    known_.insert(key);
    if (!source_.get(key, field))
      throw ConfigError(source_.where() + ": missing parameter '" + key + "'");
  }
  /// A key that is accepted but read by someone else (e.g. a deployment script).
  void allow(const std::string& key) { known_.insert(key); }
  /// `old_key` was renamed to `new_key`: throws ConfigError if the source still has the old one.
  void renamed(const std::string& old_key, const std::string& new_key) const;
  /// Throws ConfigError if the source holds a key no read() / require() / allow() named:
  /// "<where>: unknown parameter 'fit_mean' (known: a, b, c)".
  void rejectUnknown() const;

  const std::set<std::string>& known() const { return known_; }
  const ParameterSource& source() const { return source_; }

 private:
  const ParameterSource& source_;
  std::set<std::string> known_;
};

/// Collects what is wrong with a configuration, one sentence per problem.
class ConfigChecks {
 public:
  ConfigChecks& check(bool ok, const std::string& problem) {
    if (!ok) problems_.push_back(problem);
    return *this;
  }
  ConfigChecks& positive(const char* name, double value);     ///< > 0 and finite
  ConfigChecks& nonNegative(const char* name, double value);  ///< >= 0 and finite
  ConfigChecks& finite(const char* name, double value);
  /// lo <= value <= hi
  ConfigChecks& inRange(const char* name, double value, double lo, double hi);
  bool ok() const { return problems_.empty(); }
  /// "" if nothing is wrong, else every problem joined with "; ".
  std::string result() const;

 private:
  std::vector<std::string> problems_;
};

/// The loader: `config` (its defaults, or values already set) overwritten by every key that
/// `read_keys(reader, config)` names, unknown keys refused, then `config.validate()`.
/// Throws ConfigError naming the source and the problem.
template <typename Config, typename ReadKeys>
Config loadConfig(const ParameterSource& source, ReadKeys&& read_keys, Config config = Config()) {
  ConfigReader reader(source);
  read_keys(reader, config);
  reader.rejectUnknown();
  const std::string problem = config.validate();
  if (!problem.empty()) throw ConfigError(source.where() + ": " + problem);
  return config;
}

/// Parameters from a YAML mapping (a config file, a bench's options).
class YamlParameterSource : public ParameterSource {
 public:
  /// `node` must be a mapping (or null: no keys); `where` names it in messages.
  YamlParameterSource(const YAML::Node& node, std::string where);
  ~YamlParameterSource() override;
  /// Reads a YAML file; throws ConfigError naming it if it cannot be read or parsed.
  static YamlParameterSource fromFile(const std::string& path);

  std::vector<std::string> keys() const override;
  bool get(const std::string& key, bool& value) const override;
  bool get(const std::string& key, int& value) const override;
  bool get(const std::string& key, double& value) const override;
  bool get(const std::string& key, std::string& value) const override;
  bool get(const std::string& key, std::vector<double>& value) const override;
  bool get(const std::string& key, std::vector<std::string>& value) const override;
  bool get(const std::string& key, std::vector<Eigen::Vector2d>& value) const override;
  std::string where() const override { return where_; }

  YamlParameterSource(YamlParameterSource&&) noexcept;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string where_;
};

}  // namespace wheelchair_core
