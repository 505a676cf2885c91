// How `aabench score` shows one scored image (harness/measure/score.h): a short text table for
// people and a JSON object for machines. Pure formatting; the figures are the metric registry's
// that need only one image (ShownIn kInScore) and the JSON fields are results.json's columns
// (report.h: column_value), so names and encodings (NaN as null, infinities as "inf") are the
// same.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "harness/measure/compare.h"

namespace aabench {

// The results.json columns `score` reports, in order.
std::vector<std::string> score_fields();

// {<score_fields()...>}: each field under its results.json name, encoded as results.json
// encodes it. What `score --json` prints after "image", and what the Python module's score()
// returns (python/aabench_module.cpp): one list, so the two cannot drift.
nlohmann::ordered_json score_figures(const ResultRow& row);

// {"image": PATH, <score_figures(row)...>}
std::string score_json(const ResultRow& row, const std::string& image_path);

// One line per figure: name, value, what it is against.
std::string format_score(const ResultRow& row, const std::string& image_path);

}  // namespace aabench
