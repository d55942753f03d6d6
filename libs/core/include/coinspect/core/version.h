#pragma once

namespace coinspect {
// "major.minor.patch", from the CMake project version.
const char* version();
}  // namespace coinspect
