// docs/contributing.md names files and tests for each recipe; when the tree moves, a recipe that
// still names the old place misleads. Every path it names in backquotes exists, every doc it
// names exists, and every test it names as `Suite.Name` is defined in tests/.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "text_search.h"

namespace aabench {
namespace {

namespace fs = std::filesystem;

const fs::path kSource = AABENCH_SOURCE_DIR;

// tests/text_search.h's reader, with the file's presence checked.
std::string read_text(const fs::path& path) {
    EXPECT_TRUE(fs::exists(path)) << path;
    return test::read_text(path);
}

// The text between each pair of backquotes.
std::vector<std::string> quoted(const std::string& text) {
    std::vector<std::string> out;
    const std::regex code("`([^`\n]+)`");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), code);
         it != std::sregex_iterator(); ++it) {
        out.push_back((*it)[1]);
    }
    return out;
}

// Fewer than this many names checked means the page or the patterns below lost their way (the
// page names some 70 paths and a dozen tests), not that all is well.
constexpr std::size_t kMinPaths = 40;
constexpr std::size_t kMinTests = 8;

TEST(Contributing, EveryPathTheRecipesNameExists) {
    const std::string page = read_text(kSource / "docs/contributing.md");
    // A path from the top of the tree (placeholders such as <name> are not paths).
    const std::regex tree_path(
        "(methods|patterns|harness|python|tests|docs|scripts|results)/[A-Za-z0-9_./-]*|CMakeLists\\.txt|"
        "README\\.md");
    std::size_t checked = 0;
    for (const std::string& name : quoted(page)) {
        if (!std::regex_match(name, tree_path)) continue;
        ++checked;
        EXPECT_TRUE(fs::exists(kSource / name)) << name;
    }
    // Links to other docs, relative to docs/.
    const std::regex link("\\]\\(([a-z0-9-]+\\.md)[)#]");
    for (auto it = std::sregex_iterator(page.begin(), page.end(), link);
         it != std::sregex_iterator(); ++it) {
        ++checked;
        EXPECT_TRUE(fs::exists(kSource / "docs" / (*it)[1].str())) << (*it)[1];
    }
    EXPECT_GE(checked, kMinPaths);
}

TEST(Contributing, EveryTestTheRecipesNameIsDefined) {
    std::string tests;
    for (const auto& entry : fs::directory_iterator(kSource / "tests")) {
        if (entry.path().extension() == ".cpp") tests += read_text(entry.path());
    }
    const std::regex test_name("([A-Z][A-Za-z0-9]*)\\.([A-Z][A-Za-z0-9]+)");
    std::size_t checked = 0;
    for (const std::string& name : quoted(read_text(kSource / "docs/contributing.md"))) {
        std::smatch m;
        if (!std::regex_match(name, m, test_name)) continue;
        ++checked;
        // TEST(Suite, Name), TEST_F or TEST_P, as clang-format lays it out.
        EXPECT_NE(tests.find(fmt::format("({}, {})", m[1].str(), m[2].str())), std::string::npos)
            << name;
    }
    EXPECT_GE(checked, kMinTests);
}

}  // namespace
}  // namespace aabench
