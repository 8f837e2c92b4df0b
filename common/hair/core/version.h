#pragma once

#include <string>

namespace hair {

/// Project version and `git describe --dirty` of the build, e.g. "0.1.0+a1b2c3d-dirty",
/// read from hairstyle-version.txt beside the running binary (or in ../bin from it:
/// the build writes it into bin/). Without that file: "0.1.0+unknown".
const std::string& project_version();

}  // namespace hair
