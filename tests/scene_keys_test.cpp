// The places a scene-file key lives (docs/contributing.md, "A new scene-file key"): the reader's
// list of keys, docs/scene-format.md's tables, the writer, and a seed of the reader's fuzz target
// (tests/fuzz/corpus/scene_reader_fuzz/). Every key the reader takes is in the format's doc, and
// an existing optional key (the window origin) goes from its seed through reader and writer and
// back bit for bit.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "patterns/scene/scene_io.h"
#include "text_search.h"

namespace aabench {
namespace {

namespace fs = std::filesystem;

// tests/text_search.h's reader, with the file's presence checked.
std::string read_text(const fs::path& path) {
    EXPECT_TRUE(fs::exists(path)) << path;
    return test::read_text(path);
}

// The keys an "unknown key (expected one of: a, b, c)" refusal of `text` lists: the reader's
// own list, so that a key added to the reader is seen here without this file changing.
std::vector<std::string> keys_the_reader_takes(const std::string& text) {
    std::string message;
    try {
        parse_scene_json(text, "t.json");
    } catch (const InputError& e) {
        message = e.what();
    }
    const std::string lead = "unknown key (expected one of: ";
    const std::size_t from = message.find(lead);
    const std::size_t to = message.rfind(')');
    if (from == std::string::npos || to == std::string::npos || to < from) {
        ADD_FAILURE() << "not an unknown-key refusal: '" << message << "'";
        return {};
    }
    std::vector<std::string> keys;
    std::istringstream list(message.substr(from + lead.size(), to - from - lead.size()));
    for (std::string key; std::getline(list, key, ',');) {
        keys.push_back(key.substr(key.find_first_not_of(' ')));
    }
    return keys;
}

TEST(SceneKeys, EveryKeyTheReaderTakesIsInTheFormatDoc) {
    const std::string doc = read_text(fs::path(AABENCH_SOURCE_DIR) / "docs/scene-format.md");
    // The latest version's top level holds every top-level key: each a row of a key table.
    const std::vector<std::string> top = keys_the_reader_takes(
        R"({"version": 3, "width": 1, "height": 1, "shapes": [], "not_a_key": 0})");
    EXPECT_GE(top.size(), 7u);  // version 1's seven at least
    for (const std::string& key : top) {
        EXPECT_NE(doc.find("| `" + key + "`"), std::string::npos) << key << ": no table row";
    }
    // A shape's keys, for each type: named in the doc.
    for (const char* shape : {R"({"type": "polygon", "contours": [[[0, 0], [1, 0], [0, 1]]])",
                              R"({"type": "disc", "center": [0, 0], "radius": 1)",
                              R"({"type": "ring", "center": [0, 0], "inner": 1, "outer": 2)"}) {
        const std::vector<std::string> keys = keys_the_reader_takes(fmt::format(
            R"({{"version": 2, "width": 1, "height": 1, "shapes": [{}, "not_a_key": 0}}]}})",
            shape));
        EXPECT_FALSE(keys.empty()) << shape;
        for (const std::string& key : keys) {
            EXPECT_NE(doc.find("`" + key + "`"), std::string::npos) << key << ": not in the doc";
        }
    }
}

bool same_bits(double a, double b) { return std::signbit(a) == std::signbit(b) && a == b; }

TEST(SceneKeys, TheOriginSeedGoesThroughReaderAndWriter) {
    const fs::path seed =
        fs::path(AABENCH_SOURCE_DIR) / "tests/fuzz/corpus/scene_reader_fuzz/origin.json";
    const Scene read = read_scene_file(seed.string());
    EXPECT_EQ(read.origin_x, 1073741824.0);  // the seed's [2^30, -2^20 - 0.5]
    EXPECT_EQ(read.origin_y, -1048576.5);
    const std::string written = scene_to_json(read);
    EXPECT_NE(written.find("\"origin\": ["), std::string::npos) << written;
    const Scene again = parse_scene_json(written, "written.json");
    EXPECT_TRUE(same_bits(again.origin_x, read.origin_x) &&
                same_bits(again.origin_y, read.origin_y));
    EXPECT_TRUE(again == read);
}

}  // namespace
}  // namespace aabench
