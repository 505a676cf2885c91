// Sample positions inside a pixel for supersampling that is not a regular k x k grid
// (methods/ssaa.cpp, pattern=rgss|msaa). Exact by construction: every position is an integer
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
#pragma once

#include <array>
#include <vector>

namespace aabench {

struct SamplePattern {
    int denominator = 1;                      // offsets are in units of 1/denominator px
    std::vector<std::array<int, 2>> offsets;  // (x, y) from the pixel centre, y down

    std::size_t size() const { return offsets.size(); }
    // The position within the pixel, in [0, 1): 0.5 + offset / denominator.
    double x(std::size_t s) const { return 0.5 + static_cast<double>(offsets[s][0]) / denominator; }
    double y(std::size_t s) const { return 0.5 + static_cast<double>(offsets[s][1]) / denominator; }
};

// The sample counts standard_msaa_pattern knows.
inline constexpr std::array<int, 4> kStandardMsaaCounts = {2, 4, 8, 16};

// n must be one of kStandardMsaaCounts (std::invalid_argument otherwise: callers check first).
SamplePattern standard_msaa_pattern(int n);

// k >= 1.
SamplePattern rotated_grid_pattern(int k);

}  // namespace aabench
