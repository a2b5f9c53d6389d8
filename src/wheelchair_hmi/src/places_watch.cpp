#include <wheelchair_hmi/places_watch.h>

#include <sys/stat.h>

#include <exception>

namespace wheelchair_hmi {

PlacesFileWatch::PlacesFileWatch(std::string path) : path_(std::move(path)), stamp_(stampNow()) {}

PlacesFileWatch::Stamp PlacesFileWatch::stampNow() const {
  struct stat st {};
  Stamp s;
  if (::stat(path_.c_str(), &st) != 0) return s;
  s.exists = true;
  s.inode = st.st_ino;
  s.size = st.st_size;
  s.mtime_ns = static_cast<long long>(st.st_mtim.tv_sec) * 1000000000LL + st.st_mtim.tv_nsec;
  return s;
}

std::optional<std::vector<Place>> PlacesFileWatch::changed(std::string& problem) {
  problem.clear();
  const Stamp now = stampNow();
  if (now == stamp_) return std::nullopt;
  stamp_ = now;
  try {
    return loadPlaces(path_);
  } catch (const std::exception& e) {
    problem = e.what();
    return std::nullopt;
  }
}

}  // namespace wheelchair_hmi
