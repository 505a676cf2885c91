// Label placement (harness/report/label_layout.h): first free candidate, greedy in request order.
#include "harness/report/label_layout.h"

#include <algorithm>
#include <array>
#include <utility>

namespace aabench {
namespace {

// DejaVu Sans at 10 px averages about 6 px per character for digits, '=' and lower case; bold
// about 6.6. Over-estimating only leaves a little air.
constexpr double kAdvancePerPx = 0.62;
constexpr double kBoldAdvancePerPx = 0.68;
// A label's box above and below its baseline, per px of font (ascent and descent).
constexpr double kAscent = 0.8;
constexpr double kDescent = 0.25;
// Gaps between a marker's edge and its label: rings of candidates, nearest first. A label on
// the outer ring is far enough from its point to need a leader line (kLeaderGapPx and more).
constexpr std::array<double, 3> kGapsPx = {2.0, 9.0, 20.0};
constexpr double kLeaderGapPx = 15.0;

}  // namespace

double label_width(const std::string& text, double font_px, bool bold) {
    std::size_t characters = 0;
    for (unsigned char c : text) characters += (c & 0xC0) != 0x80;  // UTF-8 code points
    return static_cast<double>(characters) * font_px * (bold ? kBoldAdvancePerPx : kAdvancePerPx);
}

std::pair<double, double> nearest_point(const LabelBox& box, double x, double y) {
    return {std::clamp(x, box.x0, box.x1), std::clamp(y, box.y0, box.y1)};
}

std::vector<std::optional<PlacedLabel>> place_labels(const std::vector<LabelRequest>& requests,
                                                     const std::vector<Marker>& markers,
                                                     const LabelBox& frame) {
    std::vector<LabelBox> taken;
    for (const Marker& m : markers) taken.push_back(m.box());
    std::vector<std::optional<PlacedLabel>> out;
    for (const LabelRequest& r : requests) {
        const double w = label_width(r.text, r.font_px, r.bold);
        const double up = kAscent * r.font_px, down = kDescent * r.font_px;
        const double h = up + down;
        const double x = r.anchor.x, y = r.anchor.y, rad = r.anchor.radius;
        std::optional<PlacedLabel> placed;
        for (double gap : kGapsPx) {
            const double d = rad + gap;
            // Left edges and top edges of the candidate boxes, in order of preference.
            const std::array<std::pair<double, double>, 8> spots = {{
                {x + d, y - 0.5 * h},                // right
                {x - d - w, y - 0.5 * h},            // left
                {x - 0.5 * w, y - d - h},            // above
                {x - 0.5 * w, y + d},                // below
                {x + 0.7 * d, y - 0.7 * d - h},      // above right
                {x + 0.7 * d, y + 0.7 * d},          // below right
                {x - 0.7 * d - w, y - 0.7 * d - h},  // above left
                {x - 0.7 * d - w, y + 0.7 * d},      // below left
            }};
            for (const auto& [left, top] : spots) {
                const LabelBox box{left, top, left + w, top + h};
                if (box.x0 < frame.x0 || box.y0 < frame.y0 || box.x1 > frame.x1 ||
                    box.y1 > frame.y1) {
                    continue;
                }
                bool free = true;
                for (const LabelBox& t : taken) free = free && !box.overlaps(t);
                if (!free) continue;
                placed = PlacedLabel{box, left, top + up, gap >= kLeaderGapPx};
                break;
            }
            if (placed) break;
        }
        if (placed) taken.push_back(placed->box);
        out.push_back(placed);
    }
    return out;
}

}  // namespace aabench
