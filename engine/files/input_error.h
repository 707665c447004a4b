#pragma once
#include <stdexcept>
#include <string>

namespace patina {

// Bad input from a user's file or arguments: the message names the file and the place
// (line and column, JSON pointer or CSV line) and says what is wrong. The CLI exits with 3.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A decoder's reason for failing, never null. stb_image keeps its reason per thread and leaves it
// unset after some failures (a deflate block of the reserved type 3): a fresh thread's first
// such failure would otherwise reach std::string as a null pointer.
inline const char* decoderReason(const char* reason) {
    return reason != nullptr ? reason : "corrupt data";
}

}  // namespace patina
