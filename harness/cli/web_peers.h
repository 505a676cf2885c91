// The web peers of `compare --web-peers`: Skia (@napi-rs/canvas) and tiny-skia (@resvg/resvg-js),
// drawn by the node scripts of scripts/web-peers/ as external renderers (docs/external.md).
//
// scripts/install-deps installs the two npm packages from the committed package-lock into
// scripts/web-peers/node_modules (ignored by git). Where node or a package is missing, that peer
// is left out with its reason: the comparison runs without it.
#pragma once

#include <string>
#include <vector>

#include "harness/cli/external.h"

namespace aabench {

struct WebPeers {
    std::vector<ExternalRenderer> renderers;  // the peers found, with their package versions
    std::vector<std::string> left_out;        // one line per peer not found: which, and why
};

// The folder of the scripts: $AABENCH_WEB_PEERS when set, else scripts/web-peers of the source
// tree this binary was built from.
std::string web_peers_dir();

// Looks for node on PATH and for each package under `dir`/node_modules, and runs each script's
// `--version` once (it loads the package's native binding and prints its version).
WebPeers find_web_peers(const std::string& dir = web_peers_dir());

}  // namespace aabench
