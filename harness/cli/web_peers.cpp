// The web peers (harness/cli/web_peers.h).
#include "harness/cli/web_peers.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#ifndef AABENCH_WEB_PEERS_DIR
#define AABENCH_WEB_PEERS_DIR "scripts/web-peers"
#endif

namespace aabench {
namespace {

namespace fs = std::filesystem;

struct WebPeer {
    const char* name;     // the rows' method: external:NAME
    const char* script;   // in the peers' folder
    const char* package;  // the npm package that carries the library
    const char* library;  // what draws, for the row's method
};

constexpr WebPeer kWebPeers[] = {
    {"skia", "skia.mjs", "@napi-rs/canvas", "Skia"},
    {"resvg", "resvg.mjs", "@resvg/resvg-js", "tiny-skia"},
};

// The first `node` executable on PATH, or empty.
std::string find_node() {
    const char* path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "");
    for (std::string dir; std::getline(dirs, dir, ':');) {
        if (dir.empty()) continue;
        const fs::path candidate = fs::path(dir) / "node";
        std::error_code ec;
        if (fs::is_regular_file(candidate, ec) && ::access(candidate.c_str(), X_OK) == 0) {
            return candidate.string();
        }
    }
    return {};
}

// The "version" of an installed package's package.json, or empty when it is not installed.
std::string package_version(const fs::path& dir, const std::string& package) {
    std::ifstream in(dir / "node_modules" / package / "package.json");
    if (!in) return {};
    const nlohmann::json doc = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
    if (!doc.is_object() || !doc.contains("version") || !doc["version"].is_string()) return {};
    return doc["version"].get<std::string>();
}

std::string shell_quote(const std::string& text) {
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

}  // namespace

std::string web_peers_dir() {
    const char* dir = std::getenv("AABENCH_WEB_PEERS");
    return dir && *dir ? std::string(dir) : std::string(AABENCH_WEB_PEERS_DIR);
}

WebPeers find_web_peers(const std::string& dir) {
    WebPeers found;
    const std::string node = find_node();
    for (const WebPeer& peer : kWebPeers) {
        const fs::path script = fs::path(dir) / peer.script;
        const std::string version = package_version(dir, peer.package);
        std::string why;
        if (node.empty()) {
            why = "node is not on PATH";
        } else if (!fs::is_regular_file(script)) {
            why = fmt::format("{} is missing", script.string());
        } else if (version.empty()) {
            why = fmt::format("{} is not installed in {} (scripts/install-deps installs it)",
                              peer.package, (fs::path(dir) / "node_modules").string());
        }
        if (!why.empty()) {
            found.left_out.push_back(fmt::format("--web-peers: {} left out: {}", peer.name, why));
            continue;
        }
        ExternalRenderer r;
        r.name = peer.name;
        r.command =
            fmt::format("{} {} {{svg}} {{out}}", shell_quote(node), shell_quote(script.string()));
        r.version = fmt::format("{} via {} {}", peer.library, peer.package, version);
        found.renderers.push_back(std::move(r));
    }
    return found;
}

}  // namespace aabench
