// Sample positions (methods/scan/sampling/sample_patterns.h).
#include "methods/scan/sampling/sample_patterns.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "patterns/scene/scene.h"

namespace aabench {

namespace {

// msaa and rgss: the positions as the samples have always been taken.
void positions_from_offsets(SamplePattern& p) {
    p.positions.clear();
    for (const auto& [u, v] : p.offsets) {
        p.positions.push_back({0.5 + static_cast<double>(u) / p.denominator,
                               0.5 + static_cast<double>(v) / p.denominator});
    }
}

// The radical inverse of `index` in `base`: numerator / denominator, denominator = base^digits.
struct Fraction {
    long long numerator = 0, denominator = 1;
};
Fraction radical_inverse(int index, int base) {
    Fraction f;
    for (; index > 0; index /= base) {
        f.numerator = f.numerator * base + index % base;
        f.denominator *= base;
    }
    return f;
}

// The smallest power of `base` above n: every radical inverse of 1..n has it as a multiple of
// its denominator.
long long power_above(int n, int base) {
    long long p = 1;
    while (p <= n) p *= base;
    return p;
}

// A coordinate of a listed position: "0", "0.d...", ".d..." with 1..kMaxPositionDigits digits.
// The decimal numerator / 10^digits, or false.
bool parse_decimal(const std::string& text, long long& numerator, int& digits) {
    std::size_t at = 0;
    if (at < text.size() && text[at] == '0') ++at;
    numerator = 0;
    digits = 0;
    if (at == text.size()) return at > 0;  // "0"
    if (text[at] != '.') return false;
    for (++at; at < text.size(); ++at) {
        if (text[at] < '0' || text[at] > '9' || digits == kMaxPositionDigits) return false;
        numerator = numerator * 10 + (text[at] - '0');
        ++digits;
    }
    return digits > 0;
}

}  // namespace

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
    positions_from_offsets(p);
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
    positions_from_offsets(p);
    return p;
}

std::vector<std::array<double, 2>> halton_positions(int n) {
    std::vector<std::array<double, 2>> positions;
    for (int index = 1; index <= n; ++index) {
        const Fraction x = radical_inverse(index, 2), y = radical_inverse(index, 3);
        positions.push_back({static_cast<double>(x.numerator) / static_cast<double>(x.denominator),
                             static_cast<double>(y.numerator) / static_cast<double>(y.denominator)});
    }
    return positions;
}

SamplePattern halton_pattern(int n) {
    if (n < 1 || n > kMaxHaltonSamples) {
        throw std::invalid_argument("halton_pattern: " + std::to_string(n) + " samples");
    }
    // Offsets from the centre in units of 1/(2 P2 P3): x - 1/2 = (2 a (P2/2^m) - P2) P3 / (2 P2 P3)
    // for x = a / 2^m, and likewise for y over powers of 3. At n = 64: 1/20736 px.
    const long long p2 = power_above(n, 2), p3 = power_above(n, 3);
    SamplePattern p;
    p.denominator = static_cast<int>(2 * p2 * p3);
    for (int index = 1; index <= n; ++index) {
        const Fraction x = radical_inverse(index, 2), y = radical_inverse(index, 3);
        p.offsets.push_back(
            {static_cast<int>((2 * x.numerator * (p2 / x.denominator) - p2) * p3),
             static_cast<int>((2 * y.numerator * (p3 / y.denominator) - p3) * p2)});
    }
    p.positions = halton_positions(n);
    return p;
}

SamplePattern parse_sample_positions(const std::string& text, const std::string& what) {
    struct Parsed {
        long long numerator[2];
        int digits[2];
        double value[2];
    };
    std::vector<Parsed> items;
    int max_digits = 0;
    std::size_t start = 0;
    for (int item = 1;; ++item) {
        const std::size_t end = text.find(';', start);
        const std::string token =
            text.substr(start, end == std::string::npos ? std::string::npos : end - start);
        const std::size_t slash = token.find('/');
        Parsed parsed{};
        bool ok = slash != std::string::npos;
        for (int axis = 0; ok && axis < 2; ++axis) {
            const std::string coordinate =
                axis == 0 ? token.substr(0, slash) : token.substr(slash + 1);
            ok = parse_decimal(coordinate, parsed.numerator[axis], parsed.digits[axis]);
            if (ok) parsed.value[axis] = std::strtod(coordinate.c_str(), nullptr);
            if (ok) max_digits = std::max(max_digits, parsed.digits[axis]);
        }
        if (!ok) {
            throw InputError(fmt::format(
                "{}: positions item {} '{}' is not X/Y with X and Y decimals in [0, 1) of at most "
                "{} digits after the point",
                what, item, token, kMaxPositionDigits));
        }
        if (static_cast<int>(items.size()) == kMaxListedPositions) {
            throw InputError(fmt::format("{}: positions lists more than {} positions", what,
                                         kMaxListedPositions));
        }
        items.push_back(parsed);
        if (end == std::string::npos) break;
        start = end + 1;
    }
    // Units of 1/(2 * 10^m), m the most digits given: x - 1/2 = (2 a 10^(m - d) - 10^m) / (2 10^m)
    // for x = a / 10^d. At m = 8 the Gaussian's radius test squares at most 3 * 2 * 10^8: exact.
    long long scale = 1;
    for (int d = 0; d < max_digits; ++d) scale *= 10;
    SamplePattern p;
    p.denominator = static_cast<int>(2 * scale);
    for (const Parsed& item : items) {
        std::array<int, 2> offset{};
        for (int axis = 0; axis < 2; ++axis) {
            long long unit = 1;
            for (int d = item.digits[axis]; d < max_digits; ++d) unit *= 10;
            offset[axis] = static_cast<int>(2 * item.numerator[axis] * unit - scale);
        }
        p.offsets.push_back(offset);
        p.positions.push_back({item.value[0], item.value[1]});
    }
    return p;
}

}  // namespace aabench
