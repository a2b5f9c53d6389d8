# Faults of the command path on the running chair (the simulator + the one-process chair, as the
# demo brings them up): issue 20's findings, one rostest each (test_command_path.py).
# Included by test/CMakeLists.txt inside if(CATKIN_ENABLE_TESTING) after find_package(rostest):
#   include(faults/faults.cmake)
foreach(fault foreign_torques foreign_release supervisor_unloaded chair_hang sim_hang
        corrupt_frames power_removed frozen_encoder output_fault command_signal_lost
        foreign_switch foreign_go_to foreign_speed_limit switch_off computer_power_lost)
  add_rostest(faults/${fault}.test)
endforeach()
