// GoogleTest parameter names from method specs: every character that is not a letter or a digit
// becomes '_' ("box-multiscan:n=6" -> "box_multiscan_n_6").
#pragma once

#include <cctype>
#include <string>

namespace aabench::testing {

inline std::string spec_test_name(std::string name) {
    for (char& c : name) {
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    }
    return name;
}

// For INSTANTIATE_TEST_SUITE_P over a list of specs.
struct SpecTestName {
    template <class Info>
    std::string operator()(const Info& info) const {
        return spec_test_name(info.param);
    }
};

}  // namespace aabench::testing
