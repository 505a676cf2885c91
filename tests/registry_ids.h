// The method registry as a test parameter: every row's id (and, where asked, the other readings
// the default comparison runs); tests/test_names.h names each.
#pragma once

#include <string>
#include <vector>

#include "methods/method.h"
#include "tests/test_names.h"

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

}  // namespace aabench::testing
