# The rider's display (wheelchair_display) with the real node under Xvfb, one behaviour each:
# every state's screenshots at 1024x768 and 1920x1080 measured in pixels, pointer and dwell
# choice driving the simulated chair, the STOP area and the switch, one meaning per switch
# press, the carer's tools (deleting a place among them), speech.
foreach(display_test display_screens display_pointer display_stop display_switch display_carer
    display_speech)
  add_rostest(display/${display_test}.test)
endforeach()
