// Notices that the places file changed on disk (the carer saved or deleted a place on the
// rider's display, or edited the file), so that the HMI offers the new places without a restart.
#pragma once

#include <wheelchair_hmi/places.h>

#include <sys/types.h>
#include <optional>
#include <string>
#include <vector>

namespace wheelchair_hmi {

class PlacesFileWatch {
 public:
  /// Remembers the file as it is now (read already by the caller).
  explicit PlacesFileWatch(std::string path);

  /// The file's places if it changed since the last call (or construction), else nullopt. A
  /// changed file that cannot be read (a bad edit) gives nullopt and says why in `problem`; it
  /// is not reported again until it changes once more.
  std::optional<std::vector<Place>> changed(std::string& problem);

 private:
  struct Stamp {
    bool exists = false;
    ino_t inode = 0;  ///< a new file renamed over the old one (the display's atomic writer)
    off_t size = 0;
    long long mtime_ns = 0;
    bool operator==(const Stamp& o) const {
      return exists == o.exists && inode == o.inode && size == o.size && mtime_ns == o.mtime_ns;
    }
  };
  Stamp stampNow() const;

  std::string path_;
  Stamp stamp_;
};

}  // namespace wheelchair_hmi
