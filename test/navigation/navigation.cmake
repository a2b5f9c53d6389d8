# The navigator (wheelchair_navigator) with the whole chair in the simulator loop, one rostest
# per group of behaviours of issue 22: refusals and cancel (commands), waiting, blocked and
# resuming (person, blocked), a way blocked at the start (blocked_start).
# navigation_around.test (a way round with a second route free) is not in the suite yet. The
# drive's "end at the kitchen door" failures were no arrival handover: kitchen_door faces back
# into the living room 0.85 m inside the door, where the chair's tail cannot turn, so every route
# there ends backing in 3 m through the door (~17 s sim of the ~53 s drive); at half real time the
# drive outlasted the test's 100 s wall wait (2026-12-02 14:40: one run timed out still backing
# in at (6.71, 4.82); the run that passed got REACHED 15 ms after the controller's goal_reached,
# 52.3 s sim). The test now runs the simulator at 0.75 (69-86 s wall), but 6 runs at load
# 5-8.5 (14:50-15:10) gave 2 passes (77 and 86 s wall), 2 load stops (no_safety_permit while
# driving; the driver paused 0.12 s: command_timeout), 1 localization lost beside the obstacle
# while turning (issue 21) and 1 REACHED 0.59 m short of the goal by the truth (the controller
# ends at its estimate: presumably the localization off along the door's axis; the test now logs
# the estimate beside the truth). Run it by hand (rostest wheelchair_test navigation_around.test)
# until those hold.
foreach(navigation_test navigation_commands navigation_person navigation_blocked
    navigation_no_progress navigation_blocked_start)
  add_rostest(navigation/${navigation_test}.test)
endforeach()
