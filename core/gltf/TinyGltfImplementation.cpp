// The one translation unit that compiles tinygltf's implementation (core/gltf/TinyGltf.h says why it
// is compiled here rather than linked). Its JSON parser is nlohmann-json (nlohmann-json3-dev).
#define TINYGLTF_IMPLEMENTATION
#include "core/gltf/TinyGltf.h"
