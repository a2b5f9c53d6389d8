# The Table 2 rostests (issue 10). Included by test/CMakeLists.txt inside
# if(CATKIN_ENABLE_TESTING) after find_package(rostest):  include(table2/table2.cmake)
add_rostest(table2/table2_metrics.test)
add_rostest(table2/table2.test)
