// `rosrun wheelchair_kld kld_localizer`: the localizer nodelet in its own process.
#include <wheelchair_common/nodelet_main.h>

int main(int argc, char** argv) {
  return wheelchair_common::runNodeletMain(argc, argv, "kld_localizer",
                                           "wheelchair_kld/KldLocalizerNodelet");
}
