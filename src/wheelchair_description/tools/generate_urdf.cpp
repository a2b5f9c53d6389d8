// generate_urdf [chair.yaml] [out.urdf]: writes the chair's URDF (stdout without out.urdf).
#include <wheelchair_description/urdf_generator.h>

#include <fstream>
#include <iostream>
#include <stdexcept>

int main(int argc, char** argv) {
  using namespace wheelchair_description;
  try {
    const std::string chair = argc > 1 ? argv[1] : defaultChairParamsPath();
    const std::string urdf = chairUrdf(loadChairParams(chair));
    if (argc < 3) {
      std::cout << urdf;
      return 0;
    }
    std::ofstream out(argv[2]);
    if (!(out << urdf)) throw std::runtime_error(std::string(argv[2]) + ": cannot write");
  } catch (const std::exception& e) {
    std::cerr << "generate_urdf: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
