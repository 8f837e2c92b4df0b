#pragma once

namespace hair {

/// Project version and `git describe --dirty` of the build, e.g. "0.1.0+a1b2c3d-dirty".
const char* project_version();

}  // namespace hair
