#include <wheelchair_common/nodelet_main.h>

int main(int argc, char** argv) {
  return wheelchair_common::runNodeletMain(argc, argv, "controller",
                                           "wheelchair_controller/ControllerNodelet");
}
