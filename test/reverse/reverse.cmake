# Reverse motion (issue 24) with the whole chair in the simulator loop: leaving a side room of
# flat backwards (the study, the bathroom: parked facing into it, to the living room), the guard
# behind the chair (rear laser silent -> no reverse motion; a person stepping behind the backing
# chair -> stop). Included by test/CMakeLists.txt inside if(CATKIN_ENABLE_TESTING) after
# find_package(rostest):
#   include(reverse/reverse.cmake)
add_rostest(reverse/leave_study.test)
add_rostest(reverse/leave_bathroom.test)
add_rostest(reverse/rear_guard_silent.test)
add_rostest(reverse/rear_guard_person.test)
# back_out_dead_end.test (the navigator's back-up recovery in world loop, ~4.5 min wall) is not
# in the suite yet: 2 of 7 runs passed before the back-up's first step was fixed (672e7f7), 2 of 2
# after; one of the seven was a rear-guard stop for the corridor's own walls (the localizer's
# heading off), not understood. Run it by hand: rostest wheelchair_test back_out_dead_end.test
add_rostest(reverse/three_point_turn.test)
