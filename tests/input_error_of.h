// The message of the InputError a call throws: for tests of one-line refusals.
#pragma once

#include <functional>
#include <string>

#include "patterns/scene/scene.h"  // InputError

namespace aabench {

// The message of the InputError `f` throws, or "" if it throws none.
inline std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace aabench
