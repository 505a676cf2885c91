// The parts of the HTML report (harness/report/html_report.h) that its three files share: the
// page (html_report.cpp), the summary tables (html_table.cpp), the figure grid (html_figures.cpp).
// Internal to harness/report: nothing outside the report stage includes this.
#pragma once

#include <cstddef>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "harness/report/html_report.h"

namespace aabench::html_parts {

// One pattern's part of the page: its rows (indices into ReportData::rows) and its figures.
struct Section {
    std::string spec;
    std::string id;
    std::string name;  // file and anchor name
    std::vector<std::size_t> rows;
    const PatternFigures* figures = nullptr;
};

// A file name from a spec: letters, digits and ".-=_" kept, everything else (':', ',', '/')
// becomes '_'. Collisions are resolved by the caller.
std::string slug(const std::string& text);

// `wanted`, or wanted-2, wanted-3, ... if already taken; the result is then taken.
std::string unique_name(const std::string& wanted, std::set<std::string>& taken);

// The summary table of one pattern's rows (`members`, indices into data.rows), inside its own
// scrolling box. `json_rows` is compare_json()'s "rows" for data.rows, `definitions` its
// "definitions" (the headers' hover text).
std::string results_table(const ReportData& data, const nlohmann::ordered_json& json_rows,
                          const nlohmann::ordered_json& definitions,
                          const std::vector<std::size_t>& members);

// The cost of each world stage of a 3-D pattern (any of its rows), or empty for a 2-D one.
std::string stage_table(const ResultRow& row);

// Writes the section's images under dir/images/<name>/ and returns its figure grid.
std::string figure_grid(const std::filesystem::path& dir, const Section& section,
                        const ReportData& data);

}  // namespace aabench::html_parts
