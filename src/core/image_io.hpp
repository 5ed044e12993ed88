#pragma once
// Image files: PNG (8-bit sRGB), PFM and EXR (linear float). docs/design.md §5: PFM is
// bottom row first on disk; Image is always top row first in memory.
#include "core/tonemap.hpp"

#include <airlight/image.hpp>
#include <filesystem>

namespace airlight {

// Writes by extension: .png (tone-mapped by `tone`), .pfm, .exr (linear). Throws InputError
// for an unknown extension, Failure when the file cannot be written.
void write_image(const Image& image, const std::filesystem::path& file, const ToneMap& tone = {});

// Reads .png (sRGB decoded to linear), .pfm, .exr. Throws InputError (file, "") when
// the file is missing, unreadable or malformed.
Image read_image(const std::filesystem::path& file);
// The same from the file's bytes, by the extension of `file`, which names it in errors. A
// PNG or EXR of more than 4096×4096 pixels is refused before it is decoded.
Image decode_image(const std::string& bytes, const std::filesystem::path& file);

// sRGB transfer functions (IEC 61966-2-1), per channel.
float linear_to_srgb(float linear);
float srgb_to_linear(float encoded);

}  // namespace airlight
