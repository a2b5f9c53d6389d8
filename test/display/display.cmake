# The rider's display (wheelchair_display) with the real node under Xvfb, one behaviour each:
# every state's screenshots at 1024x768 and 1920x1080 measured in pixels, pointer and dwell
# choice driving the simulated chair, the STOP area and the switch, the carer's tools, speech.
# display_carer_delete.test (the carer deleting a place) is not registered: after the save form
# the map's clicks are not taken (issue 25, a known failure); display_carer runs the rest.
foreach(display_test display_screens display_pointer display_stop display_carer display_speech)
  add_rostest(display/${display_test}.test)
endforeach()
