#include <wheelchair_harmonic_planner/global_planner.h>

#include <cmath>
#include <stdexcept>

namespace wheelchair_harmonic_planner {

double getParam(const ParameterMap& params, const std::string& name, double fallback) {
  const auto it = params.find(name);
  if (it == params.end()) return fallback;
  size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(it->second, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != it->second.size() || !std::isfinite(value)) {
    throw std::invalid_argument("parameter " + name + " is not a finite number: '" + it->second +
                                "'");
  }
  return value;
}

std::string getParam(const ParameterMap& params, const std::string& name,
                     const std::string& fallback) {
  const auto it = params.find(name);
  return it == params.end() ? fallback : it->second;
}

bool getParam(const ParameterMap& params, const std::string& name, bool fallback) {
  const auto it = params.find(name);
  if (it == params.end()) return fallback;
  if (it->second == "true" || it->second == "1") return true;
  if (it->second == "false" || it->second == "0") return false;
  throw std::invalid_argument("parameter " + name + " is not a boolean: '" + it->second + "'");
}

}  // namespace wheelchair_harmonic_planner
