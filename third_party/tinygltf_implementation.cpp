// tinygltf's implementation, from the header libtinygltf-dev installs, for sanitized builds
// (third_party/CMakeLists.txt). stb_image comes from libstb as for libtinygltf.so.
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
