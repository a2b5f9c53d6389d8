# The controller driving wheelchair_sim on sim time (moved here from wheelchair_controller, which
# must not depend on the simulator): the paper's Figure 6, the Table 2 control protocol and the
# 90 cm doorways. Included by test/CMakeLists.txt inside if(CATKIN_ENABLE_TESTING) after
# find_package(rostest):  include(controller/controller.cmake)
# The simulator's messages and the controller's ROS dependencies (roscpp, tf2_ros, the
# messages, wheelchair_ros) come with the two packages' configs.
find_package(wheelchair_controller REQUIRED)
find_package(wheelchair_sim REQUIRED)
add_executable(controller_sim_rostest EXCLUDE_FROM_ALL controller/controller_sim_rostest.cpp)
target_include_directories(controller_sim_rostest SYSTEM PRIVATE
  ${wheelchair_controller_INCLUDE_DIRS} ${wheelchair_sim_INCLUDE_DIRS})
# The ten flat paths and the Figure 6 path: the controller's test support (same CMake project).
target_link_libraries(controller_sim_rostest wheelchair_controller_test_support
  ${wheelchair_controller_LIBRARIES} ${wheelchair_sim_LIBRARIES} gtest)
add_dependencies(controller_sim_rostest ${wheelchair_controller_EXPORTED_TARGETS}
  ${wheelchair_sim_EXPORTED_TARGETS})
add_dependencies(tests controller_sim_rostest)
foreach(scenario figure6 table2 doorway)
  add_rostest(controller/sim_${scenario}.test DEPENDENCIES controller_sim_rostest controller
    simulator)
endforeach()
