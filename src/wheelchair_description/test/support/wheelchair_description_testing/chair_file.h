// Tests and benchmarks: the chair file of this source tree (a nodelet takes `chair_file`, found
// at run time; the core takes a path).
#pragma once

#include <wheelchair_description/chair_params.h>

#include <string>

namespace wheelchair_description::test {

/// config/chair.yaml of wheelchair_description's source directory.
std::string chairFile();

/// loadChairParams(chairFile()).
ChairParams shippedChair();

}  // namespace wheelchair_description::test
