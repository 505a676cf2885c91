// The message of the InputError a call throws: for tests of one-line refusals.
#pragma once

#include <functional>
#include <string>

#include <gtest/gtest.h>

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

// A scene text and the refusal it must get: one line from "test.json: <where>" that says
// <what>.
struct SceneErrorCase {
    std::string text;
    std::string where;
    std::string what;
};

// Every case's text, parsed by `parse`, is refused so (gtest expectations, the message shown).
template <class Parse, class Cases>
void expect_scene_errors(const Cases& cases, const Parse& parse) {
    for (const SceneErrorCase& c : cases) {
        const std::string message = error_of([&] { parse(c.text); });
        EXPECT_NE(message.find("test.json: " + c.where), std::string::npos) << message;
        EXPECT_NE(message.find(c.what), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

}  // namespace aabench
