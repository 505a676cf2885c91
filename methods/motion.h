// What a temporal method is handed besides the frame's scene: the motion vectors a renderer's
// G-buffer gives (never the reference), and the opaque state a method keeps between frames.
#pragma once

#include <vector>

namespace aabench {

// Per-pixel screen-space motion of the current frame relative to the previous one.
struct MotionVectors {
    int width = 0, height = 0;
    // Row-major, one per pixel: the surface seen at pixel (x, y)'s centre (x + 0.5, y + 0.5)
    // was at (x + 0.5 - dx, y + 0.5 - dy) in the previous frame (px, y down).
    std::vector<float> dx, dy;
    // No motion: frame 0, or a still sequence (every vector zero, stored as none).
    bool empty() const { return dx.empty(); }
};

// What a temporal method keeps between the frames of one sequence (its history buffers),
// made by Method::begin and handed back to every render_frame of that sequence.
class TemporalState {
public:
    virtual ~TemporalState() = default;
};

}  // namespace aabench
