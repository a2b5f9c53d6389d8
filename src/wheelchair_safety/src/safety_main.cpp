#include <wheelchair_common/nodelet_main.h>

int main(int argc, char** argv) {
  return wheelchair_common::runNodeletMain(argc, argv, "safety", "wheelchair_safety/SafetyNodelet");
}
