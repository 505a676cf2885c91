// The method registry as a test parameter: every row's id (and, where asked, the other readings
// the default comparison runs), and a gtest name for each (a spec's punctuation as '_').
#pragma once

#include <cctype>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "methods/method.h"

namespace aabench::testing {

inline std::vector<std::string> registry_method_ids(bool with_default_run_variants = false) {
    std::vector<std::string> ids;
    for (const MethodInfo& info : method_registry()) {
        ids.push_back(info.id);
        if (!with_default_run_variants) continue;
        for (const std::string& variant : info.default_run_variants) ids.push_back(variant);
    }
    return ids;
}

struct SpecTestName {
    std::string operator()(const ::testing::TestParamInfo<std::string>& info) const {
        std::string name = info.param;
        for (char& c : name) {
            if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
        }
        return name;
    }
};

}  // namespace aabench::testing
