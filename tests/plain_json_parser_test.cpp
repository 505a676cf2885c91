// The scene reader's fast first pass (patterns/scene/plain_json_parser.h) and the faces its
// tree builder keeps out of the tree (BulkFace, patterns/scene/scene_io_detail.h).
//
// The fast parser may give up on anything, but when it does not, it must have sent exactly the
// SAX events nlohmann's parser sends, every number of the same type and bits; and it must not
// give up on the plain JSON that scene files are made of, or it would be no faster. A face
// gathered outside the tree must read as the same face read from the tree, and a face that
// turns out not to be plain part way through must be refused as before, naming its path.
#include "patterns/scene/plain_json_parser.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "input_error_of.h"
#include "json_event_log.h"
#include "patterns/scene/scene_io.h"

namespace aabench {
namespace {

using scene_io_detail::parse_plain_json;

struct Outcome {
    bool parsed = false;
    std::vector<std::string> events;
};

Outcome with_nlohmann(const std::string& text) {
    JsonEventLog log;
    const bool parsed =
        nlohmann::json::sax_parse(text, &log, nlohmann::json::input_format_t::json, true);
    return {parsed, log.events};
}

Outcome with_fast_parser(const std::string& text) {
    JsonEventLog log;
    const bool parsed = parse_plain_json(text, log);
    return {parsed, log.events};
}

// The fast parser gave up, or it agrees with nlohmann event for event.
void expect_gives_up_or_agrees(const std::string& text) {
    const Outcome fast = with_fast_parser(text);
    if (!fast.parsed) return;
    const Outcome reference = with_nlohmann(text);
    EXPECT_TRUE(reference.parsed) << "the fast parser accepted what nlohmann refuses: " << text;
    EXPECT_EQ(fast.events, reference.events) << text;
}

TEST(PlainJsonParser, PlainJsonTakesTheFastPathWithNlohmannsEvents) {
    const std::vector<std::string> plain = {
        R"({"version": 2, "width": 128, "metadata": {"a": "b c", "": ""}, "x": [true, false,
           null, [], {}, [[]], -0, 0, -7, 18446744073709551615, -9223372036854775808]})",
        "[0.5,-0.0,1e22,1e23,1E-5,2.5e+3,0.1,0.30000000000000004,9007199254740993.0]",
        "[123456789012345678901234567890.5,4.9e-324,1.7976931348623157e308,1e-22,1e-23]",
        "[9999999999999999999,10000000000000000000,-9223372036854775807,-1000000000000000000]",
        " \t\r\n[ 1 , 2 ]\n ",
        "\"~ DEL \x7f is printable enough for JSON\"",
        "-12.75e-2",
    };
    for (const std::string& text : plain) {
        const Outcome fast = with_fast_parser(text);
        EXPECT_TRUE(fast.parsed) << "gave up on plain JSON: " << text;
        EXPECT_EQ(fast.events, with_nlohmann(text).events) << text;
    }
}

TEST(PlainJsonParser, GivesUpOnWhatItLeavesToNlohmann) {
    const std::vector<std::string> left_to_nlohmann = {
        R"(["\u00e9"])",
        "[\"\xc3\xa9\"]",
        R"(["a\"b"])",
        "\xef\xbb\xbf[1]",
        "[18446744073709551616]",
        "[-9223372036854775809]",
        "[1e400]",
        "[1e-400]",
        "[1,]",
        "[01]",
        "[1.]",
        "[.5]",
        "[+1]",
        "[1e]",
        "{\"a\" 1}",
        "{\"a\":1,}",
        "[1] x",
        "[\"a\x01\"]",
        "tru",
        "[nul]",
        "",
        "   ",
        "{1: 2}",
        "[NaN]",
        "[-]",
        "[1e+]",
        "\"abc",
    };
    for (const std::string& text : left_to_nlohmann) {
        EXPECT_FALSE(with_fast_parser(text).parsed) << text;
    }
    // With the terminator inside the text, too.
    EXPECT_FALSE(with_fast_parser(std::string("[1,\0 2]", 7)).parsed);
    EXPECT_FALSE(with_fast_parser(std::string("[1]\0", 4)).parsed);
}

TEST(PlainJsonParser, EveryEdgeCaseGivesUpOrAgrees) {
    const std::vector<std::string> edges = {
        "[-0]",
        "[-0.0]",
        "[0e0]",
        "[0E+0]",
        "[-0e-0]",
        "[2.2250738585072011e-308]",
        "[2.4703282292062328e-324]",
        "[2.4703282292062327e-324]",
        "[1e0000000000000000000001]",
        "[1e-999999999999999999]",
        "[1e999999999999999999]",
        "[9223372036854775807]",
        "[0.000000000000000000000000000000000000001]",
        "[1.7976931348623159e308]",
        "[100000000000000000000000000000000000000000.0]",
        "[3.141592653589793238462643383279]",
        "{\"a\":{\"b\":[{\"c\":[]}]}}",
        "[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[1]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]",
    };
    for (const std::string& text : edges) expect_gives_up_or_agrees(text);
}

// Random numbers of every shape JSON allows (and the shortest and 17-digit forms of random
// doubles): the same type and bits as nlohmann's strtod, on the exact fast path and off it.
TEST(PlainJsonParser, RandomNumbersParseToTheSameBits) {
    constexpr int kNumbers = 20000;  // about 0.1 s
    std::mt19937_64 random(20260401);
    const auto digits = [&](int count) {
        std::string out;
        for (int k = 0; k < count; ++k) out += static_cast<char>('0' + random() % 10);
        return out;
    };
    std::string text = "[";
    for (int i = 0; i < kNumbers; ++i) {
        std::string number;
        switch (i % 4) {
            case 0:
            case 1: {
                number = random() % 3 == 0 ? "-" : "";
                std::string integer = digits(1 + static_cast<int>(random() % 22));
                if (integer.size() > 1 && integer[0] == '0') integer[0] = '1';
                number += integer;
                if (random() % 2) number += "." + digits(1 + static_cast<int>(random() % 22));
                if (random() % 2) {
                    number += fmt::format("e{}{}", random() % 2 ? "-" : "+", random() % 340);
                }
                break;
            }
            case 2:
                number = fmt::format("{}", std::bit_cast<double>(random()));
                break;
            default:
                number = fmt::format("{:.17g}", std::bit_cast<double>(random()));
                break;
        }
        // fmt writes inf and nan for some bit patterns; JSON has neither.
        if (number.find_first_of("in") != std::string::npos) number = "0";
        text += (i == 0 ? "" : ",") + number;
    }
    text += "]";
    // Split per number so that one giving up does not hide the rest.
    int fast = 0;
    std::size_t start = 1;
    while (start < text.size() - 1) {
        const std::size_t end = text.find(',', start);
        const std::string one =
            "[" + text.substr(start, (end == std::string::npos ? text.size() - 1 : end) - start) +
            "]";
        expect_gives_up_or_agrees(one);
        fast += with_fast_parser(one).parsed ? 1 : 0;
        if (end == std::string::npos) break;
        start = end + 1;
    }
    // Only numbers out of a double's range (about one in ten here) are left to nlohmann.
    EXPECT_GT(fast, kNumbers * 8 / 10);
}

// A closed unit cube whose faces take the given texts in turn.
std::string cube_with_faces(const std::vector<std::string>& faces) {
    std::string out = R"({"version": 2, "width": 16, "height": 16,
      "camera": {"eye": [3, 2.5, 4], "target": [0.5, 0.5, 0.5]},
      "objects": [{"name": "cube", "closed": true,
        "vertices": [[0,0,0],[1,0,0],[1,1,0],[0,1,0],[0,0,1],[1,0,1],[1,1,1],[0,1,1]],
        "faces": [)";
    for (std::size_t i = 0; i < faces.size(); ++i) out += (i == 0 ? "" : ", ") + faces[i];
    return out + "]}]}";
}

TEST(PlainJsonParser, GatheredFacesReadAsTheTreesFacesDo) {
    // The second list's faces have "patterns": [], which keeps each in the tree.
    const std::vector<std::string> loops = {"[0,3,2,1]", "[4,5,6,7]", "[0,1,5,4]",
                                            "[3,7,6,2]", "[0,4,7,3]", "[1,2,6,5]"};
    const std::vector<std::string> rests = {"",
                                            R"(, "reflectance": 0.5)",
                                            R"(, "mirror": 1, "reflectance": 0)",
                                            R"(, "reflectance": -0.0)",
                                            R"(, "mirror": 1e-1, "reflectance": 3)",
                                            R"(, "reflectance": 2)"};
    std::vector<std::string> gathered, in_tree;
    for (std::size_t i = 0; i < loops.size(); ++i) {
        // Keys in another order for odd faces: the loop last.
        gathered.push_back(i % 2 == 0
                               ? "{\"loop\": " + loops[i] + rests[i] + "}"
                               : "{\"mirror\": 0.5" + rests[i] + ", \"loop\": " + loops[i] + "}");
        in_tree.push_back(i % 2 == 0 ? "{\"loop\": " + loops[i] + rests[i] + ", \"patterns\": []}"
                                     : "{\"mirror\": 0.5" + rests[i] +
                                           ", \"patterns\": [], \"loop\": " + loops[i] + "}");
    }
    const Scene a = parse_scene_json(cube_with_faces(gathered), "a.json");
    const Scene b = parse_scene_json(cube_with_faces(in_tree), "b.json");
    ASSERT_TRUE(a.world && b.world);
    const auto& fa = a.world->objects[0].faces;
    const auto& fb = b.world->objects[0].faces;
    ASSERT_EQ(fa.size(), loops.size());
    ASSERT_EQ(fb.size(), loops.size());
    for (std::size_t i = 0; i < fa.size(); ++i) {
        EXPECT_EQ(fa[i].loop, fb[i].loop) << i;
        EXPECT_EQ(std::bit_cast<std::uint64_t>(fa[i].reflectance),
                  std::bit_cast<std::uint64_t>(fb[i].reflectance))
            << i;
        EXPECT_EQ(std::bit_cast<std::uint64_t>(fa[i].mirror),
                  std::bit_cast<std::uint64_t>(fb[i].mirror))
            << i;
    }
    EXPECT_TRUE(std::signbit(fa[3].reflectance));  // -0.0 kept
    EXPECT_EQ(fa[2].mirror, 1.0);
}

TEST(PlainJsonParser, AFaceThatStopsBeingPlainIsRefusedAsBefore) {
    struct Case {
        std::string face;  // the cube's second face
        std::string message;
    };
    const std::string kPath = "f.json: objects[0].faces[1]";
    const std::vector<Case> cases = {
        {R"({"loop": [4,5,6,7], "loop": [4,5,6,7]})",
         kPath + ".loop: duplicate key (each key may appear once)"},
        {R"({"reflectance": 0.5, "loop": [4,5,6,7], "reflectance": 0.5})",
         kPath + ".reflectance: duplicate key (each key may appear once)"},
        {R"({"loop": [4,5,6,7], "mirror": 0.5, "shine": 1})",
         kPath + ".shine: unknown key (expected one of: loop, reflectance, mirror, patterns)"},
        {R"({"loop": [4,5,6,7], "reflectance": null})",
         kPath + ".reflectance: expected a finite number, found null"},
        {R"({"mirror": {"a": 1}, "loop": [4,5,6,7]})",
         kPath + ".mirror: expected a finite number, found an object"},
        {R"({"mirror": 0.5, "loop": [4,5,"6",7]})",
         kPath + ".loop[2]: expected a vertex index (an integer >= 0), found the string \"6\""},
        {R"({"reflectance": 1, "loop": [4,5,[6],7]})",
         kPath + ".loop[2]: expected a vertex index (an integer >= 0), found [6]"},
        {R"({"reflectance": 1, "loop": 4})",
         kPath + ".loop: expected an array of vertex indices, found 4"},
        {R"({"reflectance": 1, "mirror": 0})", kPath + ".loop: required key is missing"},
        {R"({})", kPath + ".loop: required key is missing"},
        {R"({"loop": [4,5,6,7], "reflectance": 1e999})",
         kPath + ".reflectance: number 1e999 is not a finite double"},
        {R"({"loop": [4,5,6,17]})",
         kPath + ".loop[3]: index 17 out of range (the object has 8 vertices)"},
    };
    for (const Case& c : cases) {
        const std::string text = cube_with_faces(
            {R"({"loop": [0,3,2,1]})", c.face, R"({"loop": [0,1,5,4]})", R"({"loop": [3,7,6,2]})",
             R"({"loop": [0,4,7,3]})", R"({"loop": [1,2,6,5]})"});
        EXPECT_EQ(error_of([&] { parse_scene_json(text, "f.json"); }), c.message) << c.face;
    }
}

}  // namespace
}  // namespace aabench
