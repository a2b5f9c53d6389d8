#include <wheelchair_description_testing/chair_file.h>

namespace wheelchair_description::test {

std::string chairFile() { return WHEELCHAIR_DESCRIPTION_CHAIR_FILE; }

ChairParams shippedChair() { return loadChairParams(chairFile()); }

}  // namespace wheelchair_description::test
