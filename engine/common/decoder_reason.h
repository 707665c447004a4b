#pragma once
// A decoder's reason for failing, for every layer that decodes (image's PNG, the environment's
// and the models' images), standard C++ only.

namespace patina {

// Never null. stb_image keeps its reason per thread and leaves it unset after some failures (a
// deflate block of the reserved type 3): a fresh thread's first such failure would otherwise
// reach std::string as a null pointer.
inline const char* decoderReason(const char* reason) {
    return reason != nullptr ? reason : "corrupt data";
}

}  // namespace patina
