// PNG files that say what their codes mean, through libpng.
//
// A PNG's codes carry no meaning of their own: a file says how to turn them into light with its
// colour chunks (PNG specification, 3rd edition, §11.3.2-11.3.3): `sRGB` (the sRGB transfer
// function, IEC 61966-2-1), `gAMA` (code = light^gamma), `iCCP` (an ICC profile), `cICP`
// (coding-independent code points). OpenCV's encoder writes none of them, so every PNG aabench
// writes goes through libpng here: the 16-bit linear images with gAMA 1.0 (code = light), the
// 8-bit report views with the sRGB chunk (and the gAMA/cHRM fallback it asks for). Reading, the
// same library tells which chunks a file has (aabench score decides the decoding from them).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace aabench {

enum class PngTransfer {
    kLinear,  // gAMA 1.0: the code is the light
    kSrgb,    // the sRGB chunk (with gAMA 0.45455 and the sRGB chromaticities as fallbacks)
};

// Encodes rows of `channels` interleaved samples (1 grey, 3 RGB, 4 RGBA) of `bit_depth` 8 or
// 16 (16-bit samples in host order) into PNG bytes (zlib level 6) tagged with `transfer`.
// Throws std::runtime_error with libpng's message when libpng fails.
std::vector<std::uint8_t> encode_png(int width, int height, int channels, int bit_depth,
                                     const void* samples, PngTransfer transfer);

// What a PNG file says about its codes.
struct PngTags {
    int bit_depth = 0;
    bool srgb = false;                 // has an sRGB chunk
    std::optional<double> gamma;       // the gAMA chunk's value (code = light^gamma)
    std::optional<std::string> icc;    // an iCCP chunk: its profile name
};

// The colour chunks of the PNG at `path`; nullopt when it is not a PNG (no signature).
// libpng 1.6.39 (Debian 12) does not know cICP: such a chunk is skipped as unknown.
std::optional<PngTags> read_png_tags(const std::string& path);

}  // namespace aabench
