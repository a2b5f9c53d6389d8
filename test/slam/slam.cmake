# The chair's mapping mode in the simulator (wheelchair_slam's live nodelet in the `wheelchair`
# process with wheelchair_bringup's mapping.yaml). Included by test/CMakeLists.txt inside
# if(CATKIN_ENABLE_TESTING) after find_package(rostest):
#   include(slam/slam.cmake)
function(wheelchair_test_slam)
  find_package(catkin REQUIRED COMPONENTS geometry_msgs nav_msgs roscpp sensor_msgs std_msgs
    std_srvs tf2_ros wheelchair_msgs wheelchair_ros)
  add_executable(test_sim_slam EXCLUDE_FROM_ALL slam/test_sim_slam.cpp)
  target_include_directories(test_sim_slam PRIVATE mapping)
  target_include_directories(test_sim_slam SYSTEM PRIVATE ${catkin_INCLUDE_DIRS})
  target_link_libraries(test_sim_slam wheelchair_mapping_test_support wheelchair_hmi_core
    ${catkin_LIBRARIES} gtest)
  add_dependencies(tests test_sim_slam)
  add_dependencies(test_sim_slam ${catkin_EXPORTED_TARGETS})
  add_rostest(slam/sim_slam.test)
  add_rostest(slam/sim_slam_office.test)
endfunction()
wheelchair_test_slam()
