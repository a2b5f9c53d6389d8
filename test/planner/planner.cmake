# The planner host with both plugins (three packages together, hence here): loaded by name
# through pluginlib, planning on a published map from tf, replanning when the map changes.
# Included by test/CMakeLists.txt inside if(CATKIN_ENABLE_TESTING) after find_package(rostest):
#   include(planner/planner.cmake)
# roscpp, the messages and wheelchair_ros come with the host package's config.
find_package(wheelchair_planner REQUIRED)
add_executable(test_planner_host EXCLUDE_FROM_ALL planner/test_planner_host.cpp)
target_include_directories(test_planner_host SYSTEM PRIVATE ${wheelchair_planner_INCLUDE_DIRS})
# The corridor map: the planners' test support (same CMake project).
target_link_libraries(test_planner_host wheelchair_planner_test_support
  ${wheelchair_planner_LIBRARIES} gtest)
add_dependencies(test_planner_host ${wheelchair_planner_EXPORTED_TARGETS})
add_dependencies(tests test_planner_host)
add_rostest(planner/planner_host.test DEPENDENCIES test_planner_host planner_host
  wheelchair_planner_nodelet wheelchair_harmonic_planner_plugin wheelchair_ompl_planner_plugin)
