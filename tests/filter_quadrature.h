// Shared by the radial-filter reference tests (filter_reference_test.cpp,
// filter_reference_brute_test.cpp): the filter specs they loop over, and 10-point
// Gauss-Legendre quadrature in its plain, composite and adaptive forms.
#pragma once

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace aabench::testing {

// The defaults, a wide and a narrow support, and a Gaussian narrow enough (R > sqrt(80) sigma)
// that its far tails take the closed form instead of quadrature.
inline const std::vector<std::string> kFilterSpecs = {
    "gaussian",
    "gaussian:sigma=0.3,radius=1.7",
    "gaussian:sigma=1,radius=0.6",
    "gaussian:sigma=0.1,radius=1.2",
    "cone",
    "cone:radius=2.5",
};

inline constexpr double kGlNodes[5] = {0.97390652851717174, 0.86506336668898454,
                                       0.67940956829902444, 0.43339539412924721,
                                       0.14887433898163122};
inline constexpr double kGlWeights[5] = {0.066671344308688138, 0.14945134915058059,
                                         0.21908636251598204, 0.26926671930999635,
                                         0.29552422471475287};

inline double gauss_legendre(const std::function<double(double)>& fn, double lo, double hi) {
    const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    double sum = 0.0;
    for (int q = 0; q < 5; ++q) {
        sum += kGlWeights[q] * (fn(mid + half * kGlNodes[q]) + fn(mid - half * kGlNodes[q]));
    }
    return sum * half;
}

inline double composite(const std::function<double(double)>& fn, double lo, double hi,
                        int pieces) {
    double sum = 0.0;
    for (int k = 0; k < pieces; ++k) {
        sum += gauss_legendre(fn, lo + (hi - lo) * k / pieces, lo + (hi - lo) * (k + 1) / pieces);
    }
    return sum;
}

// Halves [lo, hi] until the two halves' sum agrees with `whole` (the rule on the whole
// interval) to tol_per_unit times the interval's length, or 40 halvings deep.
inline double adaptive(const std::function<double(double)>& fn, double lo, double hi,
                       double whole, double tol_per_unit, int depth) {
    const double mid = 0.5 * (lo + hi);
    const double left = gauss_legendre(fn, lo, mid), right = gauss_legendre(fn, mid, hi);
    if (depth > 40 || std::abs(left + right - whole) <= tol_per_unit * (hi - lo)) {
        return left + right;
    }
    return adaptive(fn, lo, mid, left, tol_per_unit, depth + 1) +
           adaptive(fn, mid, hi, right, tol_per_unit, depth + 1);
}

}  // namespace aabench::testing
