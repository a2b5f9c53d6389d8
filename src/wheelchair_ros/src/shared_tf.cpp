#include <wheelchair_ros/shared_tf.h>

#include <tf2_ros/transform_listener.h>

#include <mutex>

namespace wheelchair_ros {
namespace {

struct BufferAndListener {
  tf2_ros::Buffer buffer;  // the default cache time (10 s), as every nodelet had
  tf2_ros::TransformListener listener{buffer};  // destroyed first: stops its thread
};

}  // namespace

std::shared_ptr<tf2_ros::Buffer> sharedTfBuffer() {
  static std::mutex mutex;
  static std::weak_ptr<BufferAndListener> shared;
  std::lock_guard<std::mutex> lock(mutex);
  std::shared_ptr<BufferAndListener> holder = shared.lock();
  if (!holder) {
    holder = std::make_shared<BufferAndListener>();
    shared = holder;
  }
  return std::shared_ptr<tf2_ros::Buffer>(holder, &holder->buffer);  // keeps the listener alive
}

}  // namespace wheelchair_ros
