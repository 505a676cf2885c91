// compare --external NAME='COMMAND': someone else's renderer, run as a process on every scene of
// the comparison, its image scored like a method's render and its process timed. The protocol
// (placeholders, what is timed, what the command may print) is docs/external.md.
//
// This room runs it because it is I/O of every kind: scene files written, a process run, an
// image read; the scoring itself is harness/measure/score.h.
#pragma once

#include <string>
#include <vector>

#include "harness/measure/compare.h"

namespace aabench {

struct ExternalRenderer {
    std::string name;     // [A-Za-z0-9_.-]+; rows are method = method_id = "external:NAME"
    std::string command;  // with placeholders {scene} {pieces} {svg} {out} {width} {height}
    bool srgb = false;    // NAME:srgb=...: its PNG codes are sRGB-encoded
    // What draws and its version (the web peers: "Skia via @napi-rs/canvas 1.1.1"); when set,
    // the rows' method is "external:NAME (VERSION)" and their method_id stays "external:NAME".
    std::string version;
};

// "NAME[:srgb]=COMMAND" (the first '=' ends the name). InputError naming --external.
ExternalRenderer parse_external(const std::string& text);

// `text` single-quoted for /bin/sh (a ' inside as '\'').
std::string shell_quote(const std::string& text);

// The method_id of an external renderer's rows.
inline std::string external_method(const std::string& name) { return "external:" + name; }
// The method of its rows: the method_id, and the version where the renderer has one.
inline std::string external_method(const ExternalRenderer& r) {
    return external_method(r.name) + (r.version.empty() ? "" : " (" + r.version + ")");
}

// Runs every renderer on every pattern and scene file of `result` (as the options made them) and
// adds its rows after each pattern's rows, and its images to the figures. Startup is measured
// once per renderer and size, with an empty scene. A command that fails, writes no image or an
// image of the wrong size is an InputError naming the renderer and the pattern.
void add_external_rows(const std::vector<ExternalRenderer>& renderers,
                       const CompareOptions& options, CompareResult& result,
                       const ProgressFn& progress = {});

}  // namespace aabench
