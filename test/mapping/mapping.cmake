# The paper's mapping protocol on the simulator (wheelchair_sim drives the chair through two
# rooms of the flat world; 30 scans fused at the ground-truth poses). Included by
# test/CMakeLists.txt inside if(CATKIN_ENABLE_TESTING) after find_package(rostest):
#   include(mapping/mapping.cmake)
function(wheelchair_test_mapping)
  find_package(catkin REQUIRED COMPONENTS geometry_msgs nav_msgs roscpp sensor_msgs std_msgs tf2_ros
    wheelchair_msgs wheelchair_ros)
  add_executable(test_sim_mapping EXCLUDE_FROM_ALL mapping/test_sim_mapping.cpp)
  target_include_directories(test_sim_mapping SYSTEM PRIVATE ${catkin_INCLUDE_DIRS})
  target_link_libraries(test_sim_mapping wheelchair_mapping_test_support ${catkin_LIBRARIES}
    gtest)
  add_dependencies(tests test_sim_mapping)
  add_dependencies(test_sim_mapping ${catkin_EXPORTED_TARGETS})
  add_rostest(mapping/sim_mapping.test)
endfunction()
wheelchair_test_mapping()
