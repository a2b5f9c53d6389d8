// generate_urdf CHAIR.yaml [OUT.urdf]: writes the chair's URDF (stdout without OUT.urdf).
#include <wheelchair_description/urdf_generator.h>

#include <fstream>
#include <iostream>
#include <stdexcept>

int main(int argc, char** argv) {
  using namespace wheelchair_description;
  if (argc < 2 || argc > 3) {
    std::cerr << "usage: generate_urdf CHAIR.yaml [OUT.urdf]\n";
    return 2;
  }
  try {
    const std::string urdf = chairUrdf(loadChairParams(argv[1]));
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
