#pragma once
// Environment images from files: Radiance RGBE (.hdr, through stb_image) and OpenEXR (.exr,
// through OpenEXR 3.1), decoded to linear float RGB. Each reader checks the file's structure and
// size before the library decodes anything. NaN, infinite and negative values come out as stored:
// replaceInvalidPixels (environment/equirect.h) counts and clears them.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "common/hdr_image.h"

namespace patina {

// Each throws InputError with a message that starts with `name` and says what is wrong; rows
// in messages count from 0 at the top.
HdrImage decodeRadianceHdr(const std::vector<uint8_t>& bytes, const std::string& name);
HdrImage decodeOpenExr(const std::vector<uint8_t>& bytes, const std::string& name);
// Either of the two, told apart by content ("#?RADIANCE" or "#?RGBE", EXR's magic number), not by
// the name's extension.
HdrImage decodeEnvironmentImage(const std::vector<uint8_t>& bytes, const std::string& name);
// A regular file of at most 512 MiB, decoded by decodeEnvironmentImage; messages name `path`.
HdrImage readEnvironmentImage(const std::filesystem::path& path);

// A Radiance file of the image: RGBE (Ward 1991, "Real Pixels"), flat scanlines (no run-length
// encoding), rows top first; negative and non-finite values written as 0.
std::vector<uint8_t> encodeRadianceHdr(const HdrImage& image);

}  // namespace patina
