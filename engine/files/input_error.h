#pragma once
#include <stdexcept>
#include <string>

#include "common/decoder_reason.h"   // decoders fail with InputError and their reason

namespace patina {

// Bad input from a user's file or arguments: the message names the file and the place
// (line and column, JSON pointer or CSV line) and says what is wrong. The CLI exits with 3.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace patina
