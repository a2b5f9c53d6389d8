# The navigator (wheelchair_navigator) with the whole chair in the simulator loop, one rostest
# per group of behaviours of issue 22: refusals and cancel (commands), waiting, blocked and
# resuming (person, blocked), a way blocked at the start (blocked_start).
# navigation_around.test (a way round with a second route free) is not in the suite yet. Its
# localization loss beside the unmapped box (issue 21's "scan does not fit", 82 %) is addressed in
# the localizer (short returns left out of the inlier share, fit_max_short_share): in 3 runs of 3
# on 2026-12-02 12:30 UTC (load ~8) the chair stayed localized and went round the north side,
# but 2 drives never ended at the kitchen door (controller 'rotating_to_goal' -> 'stopping', the
# navigator's drive still active at (6.91, 4.83)) and 1 ended in a command_timeout safety stop.
# Run it by hand (rostest wheelchair_test navigation_around.test) until the end of the drive holds.
foreach(navigation_test navigation_commands navigation_person navigation_blocked
    navigation_no_progress navigation_blocked_start)
  add_rostest(navigation/${navigation_test}.test)
endforeach()
