# The speed-scaled protective field with the whole chair in the simulator loop (issue 20): a
# person appears at the edge of the stop zone at 0.3, 0.8 and 1.5 m/s. Included by
# test/CMakeLists.txt inside if(CATKIN_ENABLE_TESTING) after find_package(rostest):
#   include(field/field.cmake)
foreach(speed 0_3 0_8 1_5)
  add_rostest(field/field_${speed}.test)
endforeach()
