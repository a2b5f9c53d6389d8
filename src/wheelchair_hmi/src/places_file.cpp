#include <wheelchair_hmi/places_file.h>

#include <yaml-cpp/yaml.h>

#include <cctype>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace wheelchair_hmi {

std::string placeId(const std::string& typed) {
  std::string id;
  bool gap = false;
  for (char c : typed) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (std::isalnum(u)) {
      if (gap && !id.empty()) id += '_';
      id += static_cast<char>(std::tolower(u));
      gap = false;
    } else {
      gap = true;
    }
  }
  return id;
}

std::string placeNameProblem(const std::string& id, const std::vector<Place>& places) {
  if (id.empty()) return "the name is empty";
  for (char c : id)
    if (!(std::islower(static_cast<unsigned char>(c)) ||
          std::isdigit(static_cast<unsigned char>(c)) || c == '_'))
      return "'" + id + "' may hold only a-z, 0-9 and _";
  if (findPlace(places, id)) return "there is already a place called '" + id + "'";
  return "";
}

void savePlaces(const std::string& yaml_path, const std::vector<Place>& places) {
  YAML::Node root;
  try {
    if (std::ifstream(yaml_path)) root = YAML::LoadFile(yaml_path);
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(yaml_path + ": bad YAML: " + e.what());
  }
  if (!root.IsMap()) root = YAML::Node(YAML::NodeType::Map);
  YAML::Node list(YAML::NodeType::Sequence);
  for (const auto& p : places) {
    YAML::Node entry;
    entry.SetStyle(YAML::EmitterStyle::Flow);
    entry["name"] = p.name;
    entry["room"] = p.room;
    entry["x"] = p.pose.x;
    entry["y"] = p.pose.y;
    entry["yaw"] = p.pose.yaw;
    list.push_back(entry);
  }
  root["places"] = list;
  if (root["rooms"] && root["rooms"].IsSequence()) {
    YAML::Node rooms = root["rooms"];
    for (const auto& p : places) {
      bool known = false;
      for (const auto& r : rooms) known = known || r.as<std::string>() == p.room;
      if (!known) rooms.push_back(p.room);
    }
  }
  const std::string tmp = yaml_path + ".tmp";
  {
    std::ofstream out(tmp);
    YAML::Emitter emitter;
    emitter.SetDoublePrecision(6);
    emitter << root;
    out << "# Named places (map frame, metres / radians), grouped by room; edited on the display "
           "or by the SLAM save_place service.\n"
        << emitter.c_str() << "\n";
    if (!out) throw std::runtime_error(yaml_path + ": cannot write " + tmp);
  }
  if (std::rename(tmp.c_str(), yaml_path.c_str()) != 0)
    throw std::runtime_error(yaml_path + ": cannot replace it with " + tmp);
}

}  // namespace wheelchair_hmi
