#include <wheelchair_slam/slam_session.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace wheelchair_slam {

using wheelchair_core::Pose2D;

namespace {

constexpr const char* kScansHeader = "# wheelchair_slam graph.scans 1";

char kindLetter(EdgeKind kind) {
  switch (kind) {
    case EdgeKind::kOdometry:
      return 'o';
    case EdgeKind::kScanMatch:
      return 's';
    case EdgeKind::kLoopClosure:
      return 'l';
  }
  return '?';
}

/// A file written to PATH.tmp and renamed, so that a crash never leaves half a file.
class AtomicFile {
 public:
  explicit AtomicFile(std::string path) : path_(std::move(path)), tmp_(path_ + ".tmp") {
    file_ = std::fopen(tmp_.c_str(), "w");
    if (!file_) throw std::runtime_error(path_ + ": cannot write");
  }
  ~AtomicFile() {
    if (file_) {
      std::fclose(file_);
      std::remove(tmp_.c_str());
    }
  }
  std::FILE* get() { return file_; }
  void commit() {
    const bool ok = std::ferror(file_) == 0;
    const bool closed = std::fclose(file_) == 0;
    file_ = nullptr;
    if (!ok || !closed || std::rename(tmp_.c_str(), path_.c_str()) != 0) {
      std::remove(tmp_.c_str());
      throw std::runtime_error(path_ + ": cannot write");
    }
  }

 private:
  std::string path_, tmp_;
  std::FILE* file_ = nullptr;
};

/// Whitespace-separated numbers of one line (inf and nan as strtod reads them).
class Fields {
 public:
  Fields(const std::string& line, std::string where) : where_(std::move(where)) {
    std::istringstream s(line);
    for (std::string t; s >> t;) tokens_.push_back(t);
  }
  size_t size() const { return tokens_.size(); }
  const std::string& word(size_t i) const {
    if (i >= tokens_.size()) fail("too few fields");
    return tokens_[i];
  }
  double number(size_t i) const {
    const std::string& t = word(i);
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(t.c_str(), &end);
    if (end == t.c_str() || *end != '\0') fail("'" + t + "' is not a number");
    return v;
  }
  double finite(size_t i) const {
    const double v = number(i);
    if (!std::isfinite(v)) fail("field " + std::to_string(i + 1) + " is not finite");
    return v;
  }
  size_t index(size_t i) const {
    const double v = finite(i);
    if (v < 0 || v != std::floor(v)) fail("field " + std::to_string(i + 1) + " is not an index");
    return static_cast<size_t>(v);
  }
  Pose2D pose(size_t i) const { return {finite(i), finite(i + 1), finite(i + 2)}; }
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error(where_ + ": " + what);
  }

 private:
  std::string where_;
  std::vector<std::string> tokens_;
};

void readG2o(const std::string& path, PoseGraph& graph, std::vector<GraphEdge>& edges) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open the pose graph");
  std::string line;
  size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    const Fields f(line, path + ":" + std::to_string(number));
    if (f.size() == 0) continue;
    const std::string& tag = f.word(0);
    if (tag == "VERTEX_SE2") {
      if (f.index(1) != graph.size()) f.fail("vertices must be numbered 0, 1, 2, ... in order");
      graph.addNode(f.pose(2));
    } else if (tag == "EDGE_SE2") {
      GraphEdge e;
      e.from = f.index(1);
      e.to = f.index(2);
      e.measurement = f.pose(3);
      const double i11 = f.finite(6), i12 = f.finite(7), i13 = f.finite(8), i22 = f.finite(9),
                   i23 = f.finite(10), i33 = f.finite(11);
      e.information << i11, i12, i13, i12, i22, i23, i13, i23, i33;
      if (e.from >= graph.size() || e.to >= graph.size() || e.from == e.to)
        f.fail("edge between unknown or equal vertices");
      edges.push_back(e);
    } else if (tag != "FIX") {
      f.fail("unknown record '" + tag + "'");
    }
  }
}

}  // namespace

void writeG2o(const std::string& path, const PoseGraph& graph) {
  AtomicFile file(path);
  std::FILE* f = file.get();
  for (size_t i = 0; i < graph.size(); ++i) {
    const Pose2D& p = graph.poses()[i];
    std::fprintf(f, "VERTEX_SE2 %zu %.9g %.9g %.9g\n", i, p.x, p.y, p.yaw);
    if (i == 0) std::fprintf(f, "FIX 0\n");
  }
  for (const GraphEdge& e : graph.edges()) {
    if (!e.active) continue;
    const Eigen::Matrix3d& m = e.information;
    std::fprintf(f, "EDGE_SE2 %zu %zu %.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g\n", e.from, e.to,
                 e.measurement.x, e.measurement.y, e.measurement.yaw, m(0, 0), m(0, 1), m(0, 2),
                 m(1, 1), m(1, 2), m(2, 2));
  }
  file.commit();
}

void saveSlam(const std::string& dir, const GraphSlam& slam,
              const std::vector<wheelchair_core::LaserScan2D>& scans) {
  const std::vector<ScanRecord>& records = slam.scanRecords();
  if (scans.size() != records.size())
    throw std::invalid_argument("saveSlam: " + std::to_string(scans.size()) + " scans for " +
                                std::to_string(records.size()) + " added to the SLAM");
  const KeyframeGraph& g = slam.keyframeGraph();
  writeG2o(dir + "/graph.graph", g.graph);
  AtomicFile file(dir + "/graph.scans");
  std::FILE* f = file.get();
  std::fprintf(f, "%s\n", kScansHeader);
  std::fprintf(f,
               "# KEYFRAME node scan drive path_length odom_x odom_y odom_yaw\n"
               "# EDGE n kind (o odometry, s scan match, l loop closure): graph.graph's n-th edge\n"
               "# LOOP from to score goodness edge\n"
               "# SCAN index keyframe rel_x rel_y rel_yaw odom_x odom_y odom_yaw stamp "
               "angle_min angle_max angle_increment range_min range_max n ranges...\n");
  for (size_t k = 0; k < g.keyframes.size(); ++k) {
    const Keyframe& kf = g.keyframes[k];
    std::fprintf(f, "KEYFRAME %zu %zu %zu %.9g %.9g %.9g %.9g\n", k, kf.scan, kf.drive,
                 kf.path_length, kf.odometry.x, kf.odometry.y, kf.odometry.yaw);
  }
  std::map<size_t, size_t> written;  // edge index -> its position in graph.graph
  for (size_t i = 0; i < g.graph.edges().size(); ++i) {
    const GraphEdge& e = g.graph.edges()[i];
    if (!e.active) continue;
    const size_t n = written.size();
    written[i] = n;
    std::fprintf(f, "EDGE %zu %c\n", n, kindLetter(e.kind));
  }
  for (const LoopClosure& l : g.loops) {
    if (!l.kept || !written.count(l.edge)) continue;
    std::fprintf(f, "LOOP %zu %zu %.9g %.9g %zu\n", l.from, l.to, l.score, l.goodness,
                 written[l.edge]);
  }
  for (size_t i = 0; i < records.size(); ++i) {
    const ScanRecord& r = records[i];
    const wheelchair_core::LaserScan2D& s = scans[i];
    std::fprintf(f, "SCAN %zu %zu %.9g %.9g %.9g %.9g %.9g %.9g %.9f %.9g %.9g %.9g %.9g %.9g %zu",
                 i, r.keyframe, r.relative.x, r.relative.y, r.relative.yaw, r.odometry.x,
                 r.odometry.y, r.odometry.yaw, r.stamp, s.angle_min, s.angle_max, s.angle_increment,
                 s.range_min, s.range_max, s.ranges.size());
    for (float range : s.ranges) std::fprintf(f, " %.9g", range);
    std::fprintf(f, "\n");
  }
  file.commit();
}

SavedSlam loadSlam(const std::string& dir, const SlamConfig& config) {
  SavedSlam out;
  std::vector<GraphEdge> edges;
  readG2o(dir + "/graph.graph", out.graph.graph, edges);
  const std::string path = dir + "/graph.scans";
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open (saved with the pose graph)");
  std::string line;
  size_t number = 0;
  std::vector<char> kinds;
  while (std::getline(in, line)) {
    ++number;
    const std::string where = path + ":" + std::to_string(number);
    if (number == 1 && line != kScansHeader)
      throw std::runtime_error(where + ": not a wheelchair_slam graph.scans file");
    if (line.empty() || line[0] == '#') continue;
    const Fields f(line, where);
    const std::string& tag = f.word(0);
    if (tag == "KEYFRAME") {
      if (f.index(1) != out.graph.keyframes.size()) f.fail("keyframes must be in order");
      Keyframe k;
      k.scan = f.index(2);
      k.drive = f.index(3);
      k.path_length = f.finite(4);
      k.odometry = f.pose(5);
      out.graph.keyframes.push_back(k);
    } else if (tag == "EDGE") {
      if (f.index(1) != kinds.size()) f.fail("edges must be in order");
      const std::string& kind = f.word(2);
      if (kind != "o" && kind != "s" && kind != "l") f.fail("unknown edge kind '" + kind + "'");
      kinds.push_back(kind[0]);
    } else if (tag == "LOOP") {
      LoopClosure l;
      l.from = f.index(1);
      l.to = f.index(2);
      l.score = f.finite(3);
      l.goodness = f.finite(4);
      l.edge = f.index(5);
      out.graph.loops.push_back(l);
    } else if (tag == "SCAN") {
      if (f.index(1) != out.records.size()) f.fail("scans must be in order");
      ScanRecord r;
      r.keyframe = f.index(2);
      r.relative = f.pose(3);
      r.odometry = f.pose(6);
      r.stamp = f.finite(9);
      wheelchair_core::LaserScan2D s;
      s.stamp = r.stamp;
      s.angle_min = f.finite(10);
      s.angle_max = f.finite(11);
      s.angle_increment = f.finite(12);
      s.range_min = f.finite(13);
      s.range_max = f.finite(14);
      const size_t n = f.index(15);
      if (f.size() != 16 + n) f.fail("expected " + std::to_string(n) + " ranges");
      s.ranges.reserve(n);
      for (size_t i = 0; i < n; ++i) s.ranges.push_back(static_cast<float>(f.number(16 + i)));
      out.records.push_back(r);
      out.scans.push_back(std::move(s));
    } else {
      f.fail("unknown record '" + tag + "'");
    }
  }
  auto refuse = [&](const std::string& what) { throw std::runtime_error(dir + ": " + what); };
  if (out.graph.keyframes.size() != out.graph.graph.size())
    refuse("graph.graph has " + std::to_string(out.graph.graph.size()) + " vertices, graph.scans " +
           std::to_string(out.graph.keyframes.size()) + " keyframes");
  if (kinds.size() != edges.size())
    refuse("graph.graph has " + std::to_string(edges.size()) + " edges, graph.scans " +
           std::to_string(kinds.size()) + " edge kinds");
  if (out.graph.keyframes.empty()) refuse("the saved graph has no keyframe");
  for (size_t i = 0; i < edges.size(); ++i) {
    edges[i].kind = kinds[i] == 'o'   ? EdgeKind::kOdometry
                    : kinds[i] == 's' ? EdgeKind::kScanMatch
                                      : EdgeKind::kLoopClosure;
    out.graph.graph.addEdge(edges[i]);
  }
  for (const LoopClosure& l : out.graph.loops) {
    if (l.edge >= edges.size() || edges[l.edge].kind != EdgeKind::kLoopClosure ||
        edges[l.edge].from != l.from || edges[l.edge].to != l.to)
      refuse("a loop closure of graph.scans is not a loop edge of graph.graph");
  }
  for (Keyframe& k : out.graph.keyframes) {
    if (k.scan >= out.scans.size()) refuse("a keyframe names a scan that is not saved");
    k.points = std::make_shared<const Points>(
        scanPoints(out.scans[k.scan], config.matcher.max_range, config.matcher.point_spacing));
  }
  for (const ScanRecord& r : out.records) {
    if (r.keyframe >= out.graph.keyframes.size()) refuse("a scan names an unknown keyframe");
  }
  return out;
}

}  // namespace wheelchair_slam
