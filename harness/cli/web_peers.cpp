// The web peers (harness/cli/web_peers.h).
#include "harness/cli/web_peers.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <cstdio>
#include <utility>
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

// True when an installed package's package.json is there (the cheap test, before node runs).
bool package_installed(const fs::path& dir, const std::string& package) {
    std::error_code ec;
    return fs::is_regular_file(dir / "node_modules" / package / "package.json", ec);
}

// `node SCRIPT --version`: the script loads its package's native binding and prints
// "PACKAGE VERSION". Returns {true, that line} or {false, the first line it printed}.
std::pair<bool, std::string> probe(const std::string& node, const fs::path& script) {
    const std::string command =
        fmt::format("{} {} --version 2>&1 </dev/null", shell_quote(node), shell_quote(script.string()));
    FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe) return {false, "could not run node"};
    std::string out;
    char buffer[256];
    while (std::fgets(buffer, sizeof buffer, pipe)) out += buffer;
    const int status = ::pclose(pipe);
    const std::string line = out.substr(0, out.find('\n'));
    return {status == 0 && !line.empty(), line.empty() ? "no output" : line};
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
        std::string why, version;
        if (node.empty()) {
            why = "node is not on PATH";
        } else if (!fs::is_regular_file(script)) {
            why = fmt::format("{} is missing", script.string());
        } else if (!package_installed(dir, peer.package)) {
            why = fmt::format("{} is not installed in {} (scripts/install-deps installs it)",
                              peer.package, (fs::path(dir) / "node_modules").string());
        } else {
            // The package may be there without its native binding (another platform's, or an
            // optional dependency npm skipped): the script's own --version loads it.
            const auto [ok, line] = probe(node, script);
            if (ok) {
                version = line;
            } else {
                why = fmt::format("{} --version failed: {}", peer.script, line);
            }
        }
        if (!why.empty()) {
            found.left_out.push_back(fmt::format("--web-peers: {} left out: {}", peer.name, why));
            continue;
        }
        ExternalRenderer r;
        r.name = peer.name;
        r.command =
            fmt::format("{} {} {{svg}} {{out}}", shell_quote(node), shell_quote(script.string()));
        r.version = fmt::format("{} via {}", peer.library, version);
        found.renderers.push_back(std::move(r));
    }
    return found;
}

}  // namespace aabench
