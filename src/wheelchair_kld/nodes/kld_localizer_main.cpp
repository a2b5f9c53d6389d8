// `rosrun wheelchair_kld kld_localizer`: the localizer nodelet in its own process.
#include <wheelchair_ros/nodelet_main.h>

int main(int argc, char** argv) {
  return wheelchair_ros::runNodeletMain(argc, argv, "kld_localizer",
                                        "wheelchair_kld/KldLocalizerNodelet");
}
