// Sample positions inside a pixel for supersampling that is not a regular k x k grid
// (methods/ssaa/ssaa.cpp, pattern=rgss|msaa). Exact by construction: every position is an integer
// offset from the pixel centre in units of 1/denominator px, so the tests and the Gaussian
// weights' "inside the radius" decision work in integers.
//
//   standard_msaa_pattern(n), n = 2, 4, 8, 16: the standard multisample positions of Direct3D
//     (D3D11_STANDARD_MULTISAMPLE_PATTERN, "Standard Multisample Quality Levels" in the D3D11
//     documentation) and Vulkan (the "Standard sample locations" table of the specification,
//     section "Multisampling", used when standardSampleLocations is VK_TRUE). The two agree;
//     both give them in 1/16 px: D3D as offsets from the pixel centre, Vulkan as positions
//     from the pixel's top-left corner (Vulkan = 0.5 + D3D / 16). y grows down in both, as here.
//     16x has samples on the pixel's left and top borders (offset -8/16): positions lie in the
//     half-open pixel [0, 1)^2.
//   rotated_grid_pattern(k): k x k samples on a square grid rotated by atan(1/k) (the "n-rooks"
//     arrangement: no two samples share a row or a column of the k^2 x k^2 sub-grid). k = 2 is
//     the classic 4x rotated-grid supersampling (RGSS) and equals the standard 4x pattern above.
//   halton_positions(n) / halton_pattern(n): the Halton (2, 3) points of indices 1..n, the
//     radical inverses of the index in base 2 (x) and base 3 (y): (1/2, 1/3), (1/4, 2/3),
//     (3/4, 1/9), ... A low-discrepancy sequence: any prefix is spread evenly over the pixel,
//     which is why temporal methods jitter by it (frame t at position t mod n) and why
//     `ssaa:pattern=halton,samples=n` is the still image those methods converge to.
//   parse_sample_positions(text): a list `X/Y;X/Y;...` of decimals in [0, 1), y down from the
//     pixel's top-left corner (`ssaa:positions=...`); exact too, in units of 1/(2 * 10^digits).
#pragma once

#include <array>
#include <string>
#include <vector>

namespace aabench {

struct SamplePattern {
    int denominator = 1;                      // offsets are in units of 1/denominator px
    std::vector<std::array<int, 2>> offsets;  // (x, y) from the pixel centre, y down
    // The same positions within the pixel, in [0, 1), as the samples are taken: for msaa and
    // rgss 0.5 + offset / denominator; for halton and listed positions the double nearest the
    // position (what halton_positions returns, or what the user wrote), so that a sample is at
    // the same point as another method's that takes the same position.
    std::vector<std::array<double, 2>> positions;

    std::size_t size() const { return offsets.size(); }
    double x(std::size_t s) const { return positions[s][0]; }
    double y(std::size_t s) const { return positions[s][1]; }
};

// The sample counts standard_msaa_pattern knows.
inline constexpr std::array<int, 4> kStandardMsaaCounts = {2, 4, 8, 16};

// n must be one of kStandardMsaaCounts (std::invalid_argument otherwise: callers check first).
SamplePattern standard_msaa_pattern(int n);

// k >= 1.
SamplePattern rotated_grid_pattern(int k);

// The Halton (2, 3) points of indices 1..n (n >= 0), positions in [0, 1)^2, y down from the
// pixel's top-left corner; each coordinate is the double nearest the rational (one division).
std::vector<std::array<double, 2>> halton_positions(int n);
// The same points as a pattern, n in 1..kMaxHaltonSamples.
inline constexpr int kMaxHaltonSamples = 64;
SamplePattern halton_pattern(int n);

// `X/Y;X/Y;...`: 1..kMaxListedPositions items, each coordinate a decimal in [0, 1) with at most
// kMaxPositionDigits digits after the point ("0", "0.25", ".5"). Throws InputError naming
// `what` (e.g. "method 'ssaa'") and the item.
inline constexpr int kMaxListedPositions = 4096;
inline constexpr int kMaxPositionDigits = 8;
SamplePattern parse_sample_positions(const std::string& text, const std::string& what);

}  // namespace aabench
