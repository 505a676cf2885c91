// The scene file (JSON; version 1: 2-D shapes, version 2: also a 3-D world and exact curves,
// version 3: also a sequence, the scene's motion over frames): a strict reader
// and an exact writer. The format, every key, the limits and the error messages are in
// docs/scene-format.md.
//
// The reader accepts exactly what the format allows and nothing else: an unknown key, a wrong
// type, a duplicated key, a non-finite number, a contour of fewer than 3 points or a size out
// of range is an InputError whose message is one line, `<source>: <json path>: <problem>`,
// e.g. `scene.json: shapes[3].contours[0][2]: expected a point [x, y] of two finite numbers`.
// JSON syntax errors say where the parser stopped: `<source>: byte <n>: invalid JSON (...)`.
//
// The writer is exact: parse_scene_json(scene_to_json(s), ...) == s, every double bit for bit
// (including -0.0), metadata in the Scene's order.
#pragma once

#include <string>

#include "patterns/scene/scene.h"

namespace aabench {

// Parses scene JSON text strictly. `source` names the file in messages. Throws InputError.
// `max_vertices` is the vertex limit (kMaxSceneVertices; a parameter so tests can reach it
// without a 100 MB file).
Scene parse_scene_json(const std::string& text, const std::string& source,
                       long long max_vertices = kMaxSceneVertices);

// Reads the file at `path` (an unreadable file is an InputError naming the path and the
// reason), then parses it with `path` as the source.
Scene read_scene_file(const std::string& path);

// The scene as JSON text. Without a world: version 1 (with "version": 1, and "metadata" when
// there is any), one line per top-level key, per shape and per contour, points written as
// [x,y] without spaces. With a world: version 2, the world's keys (every one, defaults
// included) in place of "shapes", one line per top-level key, light, object's vertices and
// face. With a sequence: version 3, its "sequence" on one line after "metadata" (the frames
// only when set; every key of its motion, defaults included). Throws InputError naming the
// path if a number is not finite or a string is not valid UTF-8, as JSON cannot hold either
// faithfully.
std::string scene_to_json(const Scene& scene);

}  // namespace aabench
