# The navigator (wheelchair_navigator) with the whole chair in the simulator loop, one rostest
# per group of behaviours of issue 22: refusals and cancel (commands), waiting, blocked and
# resuming (person, blocked), a way round (around), a way blocked at the start (blocked_start).
foreach(navigation_test navigation_commands navigation_person navigation_blocked
    navigation_no_progress navigation_around navigation_blocked_start)
  add_rostest(navigation/${navigation_test}.test)
endforeach()
