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

#include <string>

#include "methods/scan/image.h"

namespace aabench {

// Errors are InputErrors "<path>: <reason>" (missing, unreadable, too large; --srgb on float
// data, which is linear by definition).
Image read_image_to_score(const std::string& path, bool srgb);

// The sRGB decoding of one normalised code in [0, 1].
double srgb_to_linear(double encoded);

}  // namespace aabench
