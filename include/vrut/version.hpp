#pragma once
// The library's version; CMakeLists.txt reads it from here. Checkpoints carry
// it, and a checkpoint from another version is refused.
#define VRUT_VERSION_STRING "0.2.0"

namespace vrut {
inline constexpr const char* version = VRUT_VERSION_STRING;
}  // namespace vrut
