# Reverse motion (issue 24) with the whole chair in the simulator loop: leaving a room the chair
# cannot turn in by backing out, and the guard behind the chair (rear laser silent -> no reverse
# motion; a person stepping behind the backing chair -> stop). Included by test/CMakeLists.txt
# inside if(CATKIN_ENABLE_TESTING) after find_package(rostest):
#   include(reverse/reverse.cmake)
foreach(reverse_test leave_study rear_guard)
  add_rostest(reverse/${reverse_test}.test)
endforeach()
