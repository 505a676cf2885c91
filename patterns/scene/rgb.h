// A colour in linear light, Rec. 709 primaries (scene file version 4, "Colour"), and its
// luminance: what 2-D shapes and 3-D worlds share (docs/colour.md).
#pragma once

#include <array>
#include <cstddef>
#include <optional>

namespace aabench {

// R, G, B.
using Rgb = std::array<double, 3>;

// The weights of linear Rec. 709 luminance, Y = 0.2126 R + 0.7152 G + 0.0722 B (ITU-R BT.709).
inline constexpr Rgb kLuminanceWeights{0.2126, 0.7152, 0.0722};
inline double luminance(const Rgb& c) {
    return kLuminanceWeights[0] * c[0] + kLuminanceWeights[1] * c[1] + kLuminanceWeights[2] * c[2];
}

// Channel `c` of a value that is grey (`grey`, the same in every channel) unless it has a
// colour (`rgb`).
inline double channel_of(double grey, const std::optional<Rgb>& rgb, int c) {
    return rgb ? (*rgb)[static_cast<std::size_t>(c)] : grey;
}

}  // namespace aabench
