# The navigator (wheelchair_navigator) with the whole chair in the simulator loop, one rostest
# per group of behaviours of issue 22: refusals and cancel (commands), waiting, blocked and
# resuming (person, blocked), a way blocked at the start (blocked_start).
# navigation_around.test (a way round with a second route free) is not in the suite yet: the
# navigator's part holds (the chair stops, waits and goes round from where it stands), but the
# localizer declares itself lost while the chair turns on the spot beside the unmapped obstacle
# ("scan does not fit the map at the estimate", 82 % of the echoes, issue 21) in 3 runs of 3 on
# 2026-12-02; run it by hand (rostest wheelchair_test navigation_around.test) until that is fixed.
foreach(navigation_test navigation_commands navigation_person navigation_blocked
    navigation_no_progress navigation_blocked_start)
  add_rostest(navigation/${navigation_test}.test)
endforeach()
