# Reverse motion (issue 24) with the whole chair in the simulator loop: the guard behind the
# chair (rear laser silent -> no reverse motion; a person stepping behind the backing chair ->
# stop). Included by test/CMakeLists.txt inside if(CATKIN_ENABLE_TESTING) after
# find_package(rostest):
#   include(reverse/reverse.cmake)
# leave_study.test (back out of the study to the living room) is not registered yet: the
# footprint search does not yet find the way out backwards within its 10 s budget (it reaches
# the hallway with the wrong heading); run it by hand: rostest wheelchair_test leave_study.test
add_rostest(reverse/rear_guard_silent.test)
add_rostest(reverse/rear_guard_person.test)
