// A colour scene's three channel values (R, G, B) as one value: what a colour engine carries
// where a grey engine carries a double (a step dv, a cell, a running sum), so that one sweep of
// the geometry composites every channel (docs/colour.md, "Who draws what").
//
// Every operation is the double operation on each component, in the order the expression
// writes it (a * b * c is (a * b) * c on each), so an engine templated on its value type does
// on component c exactly the arithmetic its grey instance does on channel c's scene: the
// planes equal the grey images of the channels bit for bit, wherever the engine's decisions
// (which rows, which chains, which pieces) depend on the geometry alone. Where the grey engine
// skips a step whose value is zero, the colour one skips it only when every component is zero
// and adds the others' +-0 otherwise: a cell or a sum is never -0 once its first block is
// summed (methods/scan/kernel/cells.h, "Why skipping is exact"), so adding a zero changes no bit.
#pragma once

#include <array>
#include <cstddef>

namespace aabench {

struct ChannelValues {
    std::array<double, 3> v{};

    double& operator[](std::size_t c) { return v[c]; }
    double operator[](std::size_t c) const { return v[c]; }
    ChannelValues& operator+=(const ChannelValues& o) {
        v[0] += o.v[0];
        v[1] += o.v[1];
        v[2] += o.v[2];
        return *this;
    }
    friend ChannelValues operator+(const ChannelValues& a, const ChannelValues& b) {
        return {{a.v[0] + b.v[0], a.v[1] + b.v[1], a.v[2] + b.v[2]}};
    }
    friend ChannelValues operator-(const ChannelValues& a, const ChannelValues& b) {
        return {{a.v[0] - b.v[0], a.v[1] - b.v[1], a.v[2] - b.v[2]}};
    }
    // IEEE multiplication commutes, so s * a and a * s are the grey code's v * s and s * v.
    friend ChannelValues operator*(const ChannelValues& a, double s) {
        return {{a.v[0] * s, a.v[1] * s, a.v[2] * s}};
    }
    friend ChannelValues operator*(double s, const ChannelValues& a) {
        return {{s * a.v[0], s * a.v[1], s * a.v[2]}};
    }
    friend ChannelValues operator/(const ChannelValues& a, double s) {
        return {{a.v[0] / s, a.v[1] / s, a.v[2] / s}};
    }
};

// Whether a step of this value changes nothing: the grey engines' `dv != 0.0` tests.
inline bool is_zero(double v) { return v == 0.0; }
inline bool is_zero(const ChannelValues& v) { return v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0; }

// One pixel of the three planes, as a colour row's resolve writes it before it is spread over
// the planes.
struct ColourPixel {
    float r = 0.0f, g = 0.0f, b = 0.0f;
};

// Rows of the three planes (R, G, B) at one image row.
using PlaneRows = std::array<float*, 3>;

}  // namespace aabench
