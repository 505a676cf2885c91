// Reading an image someone else rendered, to be scored (aabench score). The report room does
// the image I/O; this is read_image() (harness/report/image_io.h) with what a foreign file
// needs: alpha, and the sRGB transfer function.
//
// What is scored is the first channel (R of an RGB file, the grey of a grey one), composited
// over black where the file has alpha, as linear values: floats as they are (EXR, PFM;
// EXR's alpha is already associated), integers normalised to [0, 1] (8- or 16-bit PNG) and
// multiplied by their alpha. With `srgb`, integer codes are first decoded by the sRGB transfer
// function (IEC 61966-2-1: v / 12.92 up to 0.04045, ((v + 0.055) / 1.055)^2.4 above). All in
// double, rounded once to float32.
#pragma once

#include <optional>
#include <string>

#include "methods/scan/kernel/image.h"

namespace aabench {

// Errors are InputErrors "<path>: <reason>" (missing, unreadable, too large; --srgb on float
// data, which is linear by definition).
Image read_image_to_score(const std::string& path, bool srgb);

// How the codes of an integer image are turned into light.
enum class Encoding {
    kAuto,    // from the file: its tags, else its bit depth (below)
    kLinear,  // code = light (--linear)
    kSrgb,    // the sRGB transfer function (--srgb)
};

// The image, and which decoding was used and why, in words for the user.
struct ScoredImage {
    Image image;  // the first channel (a colour file's R)
    // A file of three colour channels (besides an alpha): R, G, B, decoded as `image` is, and
    // whether they differ anywhere (equal ones are a grey image stored as RGB).
    std::optional<ImagePlanes> colour;
    bool channels_differ = false;
    Encoding used = Encoding::kLinear;  // kLinear or kSrgb, or kAuto never
    double gamma = 0.0;  // > 0: decoded as light = code^(1/gamma) (a PNG's gAMA other than 1.0
                         // and sRGB's 0.45455); 0: `used` says
    std::string why;     // "the PNG's sRGB chunk", "untagged 8-bit PNG: ...", ...
};

// With kAuto: float data (EXR, PFM) are linear; a PNG's sRGB chunk means sRGB; its gAMA means
// light = code^(1/gamma) (gAMA 1.0: linear; 0.45455, the sRGB chunk's fallback value: sRGB);
// an iCCP profile named like sRGB means sRGB, any other profile is refused (give --srgb or
// --linear); an untagged 8-bit image is sRGB (what renderers write for display), an untagged
// 16-bit one linear (what aabench wrote before it tagged its PNGs). kLinear and kSrgb override.
ScoredImage read_image_to_score(const std::string& path, Encoding encoding);

// The sRGB decoding of one normalised code in [0, 1].
double srgb_to_linear(double encoded);

}  // namespace aabench
