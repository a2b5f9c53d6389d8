# The localizer in the simulator (wheelchair_sim drives the chair in the flat world, sim time),
# one rostest per behaviour: tracking, kidnapping, bad input. Included by test/CMakeLists.txt
# inside if(CATKIN_ENABLE_TESTING) after find_package(rostest):  include(kld/kld.cmake)
function(wheelchair_test_kld)
  find_package(catkin REQUIRED COMPONENTS geometry_msgs nav_msgs rosgraph_msgs roscpp
    sensor_msgs wheelchair_msgs wheelchair_ros wheelchair_sim)
  add_executable(test_kld_sim EXCLUDE_FROM_ALL kld/test_kld_sim.cpp)
  target_include_directories(test_kld_sim SYSTEM PRIVATE ${catkin_INCLUDE_DIRS})
  target_link_libraries(test_kld_sim ${catkin_LIBRARIES} gtest)
  add_dependencies(tests test_kld_sim)
  add_dependencies(test_kld_sim ${catkin_EXPORTED_TARGETS} kld_localizer wheelchair_kld_nodelets)
  add_rostest(kld/sim_tracking.test)
  add_rostest(kld/sim_kidnapping.test)
  add_rostest(kld/sim_bad_input.test)
endfunction()
wheelchair_test_kld()
