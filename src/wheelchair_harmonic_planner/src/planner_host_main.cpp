#include <wheelchair_common/nodelet_main.h>

int main(int argc, char** argv) {
  return wheelchair_common::runNodeletMain(argc, argv, "planner_host",
                                           "wheelchair_harmonic_planner/PlannerHostNodelet");
}
