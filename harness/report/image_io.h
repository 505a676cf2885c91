// Image and text files for the report stage: single-channel float images out and in, 8-bit
// display PNGs out, and every file written atomically.
//
// Atomic: the bytes go to a hidden temporary file in the target's directory
// (`.<name>.tmp-<pid>-<n>`), which is renamed over `path` only once it is complete. A reader
// never sees a half-written file, and on any failure the temporary is removed and `path` is
// left as it was (absent, or the previous file untouched). Not fsync'd: this protects against
// our own failures and concurrent readers, not against power loss.
//
// Formats, chosen by the extension (case-insensitive):
//   .exr  one float32 channel "Y" (grey) or three "R", "G", "B" (colour), linear, row 0 at the
//         top, zip compression (OpenImageIO).
//   .pfm  Portable Float Map as its format defines: grayscale "Pf" or colour "PF", rows stored
//         bottom row first, little-endian (scale -1.0); written directly (image_io.cpp says why).
//   .png  16-bit grey or RGB, code = round(clamp(v, 0, 1) * 65535), NaN written as 0 (libpng).
//         Linear values, no gamma applied, and the file says so with gAMA 1.0, so that a
//         reader (aabench score, a viewer that honours gAMA) decodes the codes as light; a
//         report that wants a display transform applies it itself and says so
//         (docs/architecture.md, "Conventions").
#pragma once

#include <cstdint>
#include <string>

#include "methods/scan/kernel/image.h"

namespace aabench {

// Writes a single-channel float image, atomically. Throws InputError "<path>: <reason>" for an
// unknown extension (listing .exr|.pfm|.png), a missing directory, an empty or inconsistent
// image, or any write failure.
void write_image(const std::string& path, const Image& image);
// The same for an image of 1 or 3 planes (a colour scene's R, G, B): EXR channels R, G, B; PFM
// "PF"; PNG 16-bit RGB, linear codes (gAMA 1.0). One plane is the grey file above.
void write_image(const std::string& path, const ImagePlanes& planes);

// Writes an 8-bit display image as PNG, with the same atomic discipline and errors. `pixels`
// holds width x height pixels of `channels` interleaved 8-bit values (1 grey, 3 RGB, 4 RGBA),
// row 0 at the top, already in the display's encoding: the caller says which (a report's
// sRGB-encoded views, colour-mapped error maps). Encoded in memory by libpng with the sRGB chunk
// and written with the checked write, as 16-bit PNGs are (image_io.cpp says why); the 16-bit
// PNGs of write_image carry gAMA 1.0 (linear codes). `path` must end in .png.
void write_display_png(const std::string& path, int width, int height, int channels,
                       const std::uint8_t* pixels);

// Writes text (CSV, JSON, HTML) with the same atomic discipline and errors.
void write_text_file(const std::string& path, const std::string& contents);

// Reads the first channel of any image OpenImageIO can read (EXR, PFM, PNG, TIFF, ...) as float:
// integer formats are normalised to [0, 1], a PFM's bottom-up rows are put top-down, an EXR's
// data window is returned. A missing, unreadable, truncated, mistyped or oversized
// (check_image_size) file is an InputError "<path>: <reason>", never a crash.
Image read_image(const std::string& path);
// Every channel as planes: 1 (grey: a file of one channel, or two, grey and alpha) or 3 (the
// first three of a file of 3 or 4: R, G, B, an alpha dropped). Otherwise as read_image.
ImagePlanes read_image_planes(const std::string& path);

}  // namespace aabench
