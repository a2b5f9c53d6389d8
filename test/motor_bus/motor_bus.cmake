# The simulator behind the real base driver on the UDP motor bus (two packages together, hence
# here: the simulator plays the motor controller through wheelchair_can, not through the
# driver): commands (the drive channel of the test process, which loads the driver nodelet) -> driver -> CAN frames over UDP -> emulated motor controller ->
# simulated wheels -> encoder frames -> the driver's /odom, against the simulator's truth.
# Included by test/CMakeLists.txt inside if(CATKIN_ENABLE_TESTING) after find_package(rostest):
#   include(motor_bus/motor_bus.cmake)
function(wheelchair_test_motor_bus)
  find_package(catkin REQUIRED COMPONENTS nav_msgs nodelet roscpp wheelchair_msgs wheelchair_ros)
  add_executable(test_sim_bus EXCLUDE_FROM_ALL motor_bus/test_sim_bus.cpp)
  target_include_directories(test_sim_bus SYSTEM PRIVATE ${catkin_INCLUDE_DIRS})
  # waitFor: the simulator's test support (same CMake project).
  target_link_libraries(test_sim_bus wheelchair_sim_testing ${catkin_LIBRARIES} gtest)
  add_dependencies(test_sim_bus ${catkin_EXPORTED_TARGETS})
  add_dependencies(tests test_sim_bus)
  add_rostest(motor_bus/bus.test DEPENDENCIES test_sim_bus simulator wheelchair_sim_nodelet
    base_driver wheelchair_base_driver_nodelet)
endfunction()
wheelchair_test_motor_bus()
