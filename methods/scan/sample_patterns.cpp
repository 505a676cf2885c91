// Sample positions (methods/scan/sample_patterns.h).
#include "methods/scan/sample_patterns.h"

#include <stdexcept>
#include <string>

namespace aabench {

SamplePattern standard_msaa_pattern(int n) {
    // D3D11_STANDARD_MULTISAMPLE_PATTERN / Vulkan standard sample locations, in 1/16 px from the
    // pixel centre, in the order of the tables (sample index s).
    SamplePattern p;
    p.denominator = 16;
    switch (n) {
        case 2:
            p.offsets = {{4, 4}, {-4, -4}};
            break;
        case 4:
            p.offsets = {{-2, -6}, {6, -2}, {-6, 2}, {2, 6}};
            break;
        case 8:
            p.offsets = {{1, -3}, {-1, 3}, {5, 1}, {-3, -5}, {-5, 5}, {-7, -1}, {3, 7}, {7, -7}};
            break;
        case 16:
            p.offsets = {{1, 1},  {-1, -3}, {-3, 2},  {4, -1}, {-5, -2}, {2, 5},  {5, 3}, {3, -5},
                         {-2, 6}, {0, -7},  {-4, -6}, {-6, 4}, {-8, 0},  {7, -4}, {6, 7}, {-7, -8}};
            break;
        default:
            throw std::invalid_argument("no standard multisample pattern of " + std::to_string(n) +
                                        " samples");
    }
    return p;
}

SamplePattern rotated_grid_pattern(int k) {
    // Sample (a, b), a, b in [0, k), sits in cell (column, row) = (b k + k - 1 - a, a k + b) of
    // the k^2 x k^2 sub-grid: the basis steps (k, -1) and (1, k) per unit of b and a are
    // orthogonal and of equal length (a square grid rotated by atan(1/k)), and column and row
    // are each a bijection onto [0, k^2). Cell centres are (2 c + 1) / (2 k^2) px from the
    // pixel's corner, i.e. 2 c + 1 - k^2 in units of 1/(2 k^2) from its centre.
    SamplePattern p;
    const int cells = k * k;
    p.denominator = 2 * cells;
    for (int a = 0; a < k; ++a) {
        for (int b = 0; b < k; ++b) {
            const int column = b * k + (k - 1 - a), row = a * k + b;
            p.offsets.push_back({2 * column + 1 - cells, 2 * row + 1 - cells});
        }
    }
    return p;
}

}  // namespace aabench
