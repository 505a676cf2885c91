// gl_raster_p.h's driver path: an OSMesa context per thread, GL 4.5 core, framebuffer objects.
//
// Drawing a shape (stencil-then-cover, the usual GPU path fill; docs/gl-msaa.md):
//   1. stencil: colour and depth writes off, every contour drawn as a triangle fan from its
//      first vertex, front faces incrementing the stencil and back faces decrementing it (both
//      wrapping). Each sample then holds the shape's winding number at it, mod 256: the fan's
//      inner edges are shared by two triangles, which GL's rasterisation rules light exactly
//      once, so they cancel, and whatever the anchor, the counts add up to the winding number.
//   2. cover: the shape's bounding box drawn with its value where the stencil is not zero
//      (nonzero rule), resetting the stencil to zero on the way. In 2-D the later shape simply
//      overwrites (the scene's compositing order); in 3-D the cover also passes the depth test
//      (GL_GEQUAL on the face's depth plane: nearer or equal wins, ties to the later shape as
//      in methods/scan/sampling/point_sampling.h) and writes its depth.
// A winding number that is a nonzero multiple of 256 reads as outside; no pattern comes near.
//
// Exact vertices. The driver rounds window coordinates to 1/256 px. We round each vertex to
// that grid ourselves, in double, in the image's frame, and draw every tile with the same
// 512 x 512 viewport, so ndc = (x - x0) / 256 - 1 for the tile's integer origin x0: a multiple
// of 2^-16 below 64 in magnitude, exact in float, and the driver's viewport transform
// (ndc * 256 + 256) is exact again. A vertex therefore reaches the rasteriser at the same
// sub-pixel position whatever the tile or band, and a banded render is the whole one bit for
// bit. Contours reaching farther than kSafeDistancePx from a tile (where float would round)
// are first clipped (Sutherland–Hodgman, which keeps every winding number inside the window).
//
// Orientation. Image row j is drawn at window row j - y0 (so the image is upside down in GL's
// y-up frame) and read back by glReadPixels in the order it comes, first row first: no flip
// anywhere. GL's sample position (sx, sy) lies sy above the pixel's bottom edge in window
// coordinates, which is sy below the pixel's top edge in the image: gl_sample_positions returns
// (sx, sy) as they are. With this, llvmpipe's 4x positions are exactly the Direct3D / Vulkan
// standard 4x pattern in the image frame (methods/scan/sampling/sample_patterns.h).
#define GL_GLEXT_PROTOTYPES 1
#include "methods/gl_msaa/gl_raster_p.h"

#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <fmt/format.h>
#include <malloc.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <string>

#include "methods/scan/kernel/peer_coverage.h"
#include "patterns/scene/curves.h"

namespace aabench {
namespace {

// Farther than this from a tile's origin, (x - x0) no longer fits float's 24 bits at 1/256 px
// (2^14 px needs 22): such contours are clipped to the tile grown by kClipMarginPx first.
constexpr double kSafeDistancePx = 16384.0;
// Wide enough that the clip's new edges lie far outside the tile (their rounding to 1/256 px
// tilts an edge inside the tile by at most 2^-9 x 512 / 4096 px), small enough to stay safe.
constexpr double kClipMarginPx = 4096.0;

constexpr const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
void main() { gl_Position = vec4(position, 1.0); }
)";
// The value of the shape at the fragment: its constant (gx = gy = 0: exactly the float value)
// or its affine value plane, evaluated once per pixel at the pixel centre (gl_FragCoord), as
// MSAA shades once per pixel and writes the result to every covered sample.
constexpr const char* kFragmentShader = R"(#version 330 core
uniform vec3 value_plane;
layout(location = 0) out float value;
void main() {
    value = value_plane.x + value_plane.y * gl_FragCoord.x + value_plane.z * gl_FragCoord.y;
}
)";

// A colour target and its depth-stencil, multisampled when samples > 1, with the single-
// sample float target it is resolved into (samples > 1 only).
struct Target {
    GLuint fbo = 0, color = 0, depth_stencil = 0;
    GLuint resolve_fbo = 0, resolve_color = 0;
    int width = 0, height = 0;  // grown as needed, never beyond kGlTileSidePx
};

// What one shape contributes to a tile's vertex buffer.
struct ShapeDraw {
    int fan_first = 0, fan_count = 0;  // its contours' fans in the fan lists
    int cover_first = 0;               // its bounding box: 4 vertices, a triangle strip
    float plane[3] = {0.0f, 0.0f, 0.0f};
};

constexpr int kGlTrimThresholdBytes = 512 << 20;
constexpr int kGlMmapThresholdBytes = 32 << 20;

class GlContext {
public:
    GlContext() {
        configure_driver_once();
        const int attribs[] = {OSMESA_FORMAT,
                               OSMESA_RGBA,
                               OSMESA_DEPTH_BITS,
                               0,
                               OSMESA_STENCIL_BITS,
                               0,
                               OSMESA_PROFILE,
                               OSMESA_CORE_PROFILE,
                               OSMESA_CONTEXT_MAJOR_VERSION,
                               4,
                               OSMESA_CONTEXT_MINOR_VERSION,
                               5,
                               0};
        context_ = OSMesaCreateContextAttribs(attribs, nullptr);
        if (context_ == nullptr) throw std::runtime_error("gl-msaa: OSMesa gave no GL 4.5 context");
        // The default framebuffer is a 1x1 placeholder: everything is drawn into our FBOs.
        if (!OSMesaMakeCurrent(context_, placeholder_, GL_UNSIGNED_BYTE, 1, 1)) {
            throw std::runtime_error("gl-msaa: OSMesaMakeCurrent failed");
        }
        GLint max_samples = 0;
        glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
        if (max_samples < 4) {
            throw std::runtime_error(
                fmt::format("gl-msaa: the driver offers {} samples, 4 are needed", max_samples));
        }
        program_ = link_program();
        plane_location_ = glGetUniformLocation(program_, "value_plane");
        glGenVertexArrays(1, &vao_);
        glBindVertexArray(vao_);
        glGenBuffers(1, &vbo_);
        glBindBuffer(GL_ARRAY_BUFFER, vbo_);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
        glEnableVertexAttribArray(0);
        glUseProgram(program_);
        glDisable(GL_CULL_FACE);
        glEnable(GL_SCISSOR_TEST);
        glEnable(GL_DEPTH_CLAMP);  // cover quads reach the depth range's ends exactly
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
    }
    ~GlContext() { OSMesaDestroyContext(context_); }
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;

    // The target for `samples` (1 or 4), at least width x height, bound for drawing.
    Target& target(int samples, int width, int height) {
        Target& t = targets_[samples > 1 ? 1 : 0];
        if (t.width < width || t.height < height) {
            // Grown to the tile at once when it must grow at all: one reallocation at most.
            allocate(t, samples, std::max(width, t.width > 0 ? kGlTileSidePx : width),
                     std::max(height, t.height > 0 ? kGlTileSidePx : height));
        }
        glBindFramebuffer(GL_FRAMEBUFFER, t.fbo);
        return t;
    }

    void draw_tile(const Scene& scene, int samples, int x0, int y0, int tile_w, int tile_h,
                   const double depth_range[2], Image& out);

private:
    static void configure_driver_once() {
        static std::once_flag once;
        std::call_once(once, [] {
            // Read by Mesa when it makes its screen, i.e. before the first context; a value the
            // user set is kept (overwrite = 0).
            setenv("LP_NUM_THREADS", "0", 0);
            setenv("MESA_SHADER_CACHE_DISABLE", "true", 0);
            // glibc hands the heap's free top back to the system past a threshold that adapts
            // to the largest block freed, and maps large blocks afresh: llvmpipe's batches,
            // freed and reallocated draw after draw, then paid a page fault per page each time
            // (the 100,000 triangles of a fan: 960,000 faults, 3.7 s of 5.9 s in the kernel).
            // Fixed thresholds (keep 512 MiB freed; blocks below 32 MiB, the most glibc takes,
            // from the heap) make it 2.3 s. Process-wide, so only once a GL context is wanted:
            // the exact stages keep glibc's adaptive thresholds, which suit them better
            // (docs/building.md, "Known traps").
            mallopt(M_TRIM_THRESHOLD, kGlTrimThresholdBytes);
            mallopt(M_MMAP_THRESHOLD, kGlMmapThresholdBytes);
        });
    }

    static GLuint compile(GLenum kind, const char* source) {
        const GLuint shader = glCreateShader(kind);
        glShaderSource(shader, 1, &source, nullptr);
        glCompileShader(shader);
        GLint ok = 0;
        glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
        if (!ok) throw std::runtime_error("gl-msaa: a shader did not compile");
        return shader;
    }

    static GLuint link_program() {
        const GLuint program = glCreateProgram();
        glAttachShader(program, compile(GL_VERTEX_SHADER, kVertexShader));
        glAttachShader(program, compile(GL_FRAGMENT_SHADER, kFragmentShader));
        glLinkProgram(program);
        GLint ok = 0;
        glGetProgramiv(program, GL_LINK_STATUS, &ok);
        if (!ok) throw std::runtime_error("gl-msaa: the shader program did not link");
        return program;
    }

    static void allocate(Target& t, int samples, int width, int height) {
        if (t.fbo != 0) {
            glDeleteFramebuffers(1, &t.fbo);
            glDeleteRenderbuffers(1, &t.color);
            glDeleteRenderbuffers(1, &t.depth_stencil);
            if (t.resolve_fbo != 0) {
                glDeleteFramebuffers(1, &t.resolve_fbo);
                glDeleteRenderbuffers(1, &t.resolve_color);
            }
            t = Target{};
        }
        // samples = 1: a plain single-sample target (one sample at the pixel centre), not a
        // one-sample multisample one.
        const GLsizei ms = samples > 1 ? samples : 0;
        glGenRenderbuffers(1, &t.color);
        glBindRenderbuffer(GL_RENDERBUFFER, t.color);
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, ms, GL_R32F, width, height);
        glGenRenderbuffers(1, &t.depth_stencil);
        glBindRenderbuffer(GL_RENDERBUFFER, t.depth_stencil);
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, ms, GL_DEPTH32F_STENCIL8, width, height);
        glGenFramebuffers(1, &t.fbo);
        glBindFramebuffer(GL_FRAMEBUFFER, t.fbo);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, t.color);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                                  t.depth_stencil);
        check_complete("multisample target");
        if (samples > 1) {
            glGenRenderbuffers(1, &t.resolve_color);
            glBindRenderbuffer(GL_RENDERBUFFER, t.resolve_color);
            glRenderbufferStorage(GL_RENDERBUFFER, GL_R32F, width, height);
            glGenFramebuffers(1, &t.resolve_fbo);
            glBindFramebuffer(GL_FRAMEBUFFER, t.resolve_fbo);
            glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                      t.resolve_color);
            check_complete("resolve target");
        }
        if (ms > 0) {
            glBindFramebuffer(GL_FRAMEBUFFER, t.fbo);
            GLint got = 0;
            glGetIntegerv(GL_SAMPLES, &got);
            if (got != samples) {
                throw std::runtime_error(
                    fmt::format("gl-msaa: asked the driver for {} samples, got {}", samples, got));
            }
        }
        t.width = width;
        t.height = height;
    }

    static void check_complete(const char* what) {
        if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
            throw std::runtime_error(fmt::format("gl-msaa: the driver's {} is incomplete", what));
        }
    }

    void build_tile(const Scene& scene, int x0, int y0, int tile_w, int tile_h,
                    const double depth_range[2]);

    OSMesaContext context_ = nullptr;
    unsigned char placeholder_[4] = {0, 0, 0, 0};
    GLuint program_ = 0, vao_ = 0, vbo_ = 0;
    GLint plane_location_ = -1;
    std::size_t vbo_capacity_ = 0;
    Target targets_[2];
    // Per tile, kept between draws (a warm render allocates nothing of ours).
    std::vector<float> vertices_;
    std::vector<GLint> fan_firsts_;
    std::vector<GLsizei> fan_counts_;
    std::vector<ShapeDraw> shapes_;
    Contour curve_scratch_;
};

GlContext& thread_context() {
    thread_local GlContext context;
    return context;
}

// The inscribed polygon of a circle with sagitta <= kGlCurveSagittaPx, clockwise on screen (an
// outer boundary) or counter-clockwise (a ring's hole), as patterns/scene/curves.h makes them,
// into `out` (its memory reused).
void circle_polygon_into(Point center, double radius_px, bool clockwise, Contour& out) {
    const int n = curve_segment_count(radius_px, kGlCurveSagittaPx);
    out.resize(static_cast<std::size_t>(n));
    const double step = 2.0 * std::numbers::pi / n;
    for (int k = 0; k < n; ++k) {
        const double a = (clockwise ? k : -k) * step;
        out[k] = {center.x + radius_px * std::cos(a), center.y + radius_px * std::sin(a)};
    }
}

double snap(double v) { return std::nearbyint(v / kGlVertexGridPx) * kGlVertexGridPx; }

// The face's depth plane mapped onto GL's normalised depth: [lo, hi] of 1/z_v (the whole
// scene's, so every tile and band maps alike) onto [-1, 1]; larger 1/z_v is nearer and wins.
float depth_ndc(const Shape& shape, double x, double y, const double range[2]) {
    if (!shape.inv_depth || range[1] <= range[0]) return -1.0f;
    return static_cast<float>(2.0 * (shape.inv_depth->at(x, y) - range[0]) / (range[1] - range[0]) -
                              1.0);
}

// The scene-wide range of 1/z_v over the corners of every shape's bounding box (the depth
// planes are affine, so this bounds them over every cover quad). {0, 0} for a 2-D scene.
void scene_depth_range(const Scene& scene, double range[2]) {
    range[0] = range[1] = 0.0;
    bool first = true;
    for (const Shape& shape : scene.shapes) {
        if (!shape.inv_depth) continue;
        double x_lo = HUGE_VAL, x_hi = -HUGE_VAL, y_lo = HUGE_VAL, y_hi = -HUGE_VAL;
        for (const Contour& c : shape.contours) {
            for (const Point& p : c) {
                x_lo = std::min(x_lo, p.x), x_hi = std::max(x_hi, p.x);
                y_lo = std::min(y_lo, p.y), y_hi = std::max(y_hi, p.y);
            }
        }
        if (x_lo > x_hi) continue;
        // Clamped to the image grown by one pixel: cover quads never reach farther.
        x_lo = std::clamp(x_lo, -1.0, scene.width + 1.0),
        x_hi = std::clamp(x_hi, -1.0, scene.width + 1.0);
        y_lo = std::clamp(y_lo, -1.0, scene.height + 1.0),
        y_hi = std::clamp(y_hi, -1.0, scene.height + 1.0);
        for (const double x : {x_lo, x_hi}) {
            for (const double y : {y_lo, y_hi}) {
                const double v = shape.inv_depth->at(x, y);
                if (first || v < range[0]) range[0] = v;
                if (first || v > range[1]) range[1] = v;
                first = false;
            }
        }
    }
}

void GlContext::build_tile(const Scene& scene, int x0, int y0, int tile_w, int tile_h,
                           const double depth_range[2]) {
    vertices_.clear();
    fan_firsts_.clear();
    fan_counts_.clear();
    shapes_.clear();
    const double scale = 2.0 / kGlTileSidePx;
    auto push = [&](double x, double y, float z) {
        vertices_.push_back(static_cast<float>((x - x0) * scale - 1.0));
        vertices_.push_back(static_cast<float>((y - y0) * scale - 1.0));
        vertices_.push_back(z);
    };
    const double far_lo_x = x0 - kSafeDistancePx, far_hi_x = x0 + kSafeDistancePx;
    const double far_lo_y = y0 - kSafeDistancePx, far_hi_y = y0 + kSafeDistancePx;
    for (const Shape& shape : scene.shapes) {
        ShapeDraw draw;
        const std::size_t vertex_start = vertices_.size();
        draw.fan_first = static_cast<int>(fan_firsts_.size());
        double x_lo = HUGE_VAL, x_hi = -HUGE_VAL, y_lo = HUGE_VAL, y_hi = -HUGE_VAL;
        // A disc or ring: its boundary circles re-polygonised at the driver's precision (see
        // kGlCurveSagittaPx); any other shape: its contours.
        const std::size_t contour_count =
            shape.circle ? (shape.circle->is_disc() ? 1 : 2) : shape.contours.size();
        for (std::size_t c = 0; c < contour_count; ++c) {
            if (shape.circle) {
                const Circle& circle = *shape.circle;
                circle_polygon_into(circle.center, c == 0 ? circle.outer : circle.inner, c == 0,
                                    curve_scratch_);
            }
            const Contour& original = shape.circle ? curve_scratch_ : shape.contours[c];
            const bool far = std::any_of(original.begin(), original.end(), [&](const Point& p) {
                return !(p.x >= far_lo_x && p.x <= far_hi_x && p.y >= far_lo_y && p.y <= far_hi_y);
            });
            // Only hostile scenes get here: the clip allocates, ordinary contours do not.
            const Contour clipped =
                far ? clip_contour(original, x0 - kClipMarginPx, y0 - kClipMarginPx,
                                   x0 + tile_w + kClipMarginPx, y0 + tile_h + kClipMarginPx)
                    : Contour{};
            const Contour& contour = far ? clipped : original;
            if (contour.size() < 3) continue;
            fan_firsts_.push_back(static_cast<GLint>(vertices_.size() / 3));
            fan_counts_.push_back(static_cast<GLsizei>(contour.size()));
            for (const Point& p : contour) {
                const double x = snap(p.x), y = snap(p.y);
                push(x, y, 0.0f);
                x_lo = std::min(x_lo, x), x_hi = std::max(x_hi, x);
                y_lo = std::min(y_lo, y), y_hi = std::max(y_hi, y);
            }
        }
        draw.fan_count = static_cast<int>(fan_firsts_.size()) - draw.fan_first;
        // The cover quad: the bounding box, cut to the tile grown by a pixel.
        x_lo = std::max(x_lo, x0 - 1.0), x_hi = std::min(x_hi, x0 + tile_w + 1.0);
        y_lo = std::max(y_lo, y0 - 1.0), y_hi = std::min(y_hi, y0 + tile_h + 1.0);
        if (draw.fan_count == 0 || x_lo >= x_hi || y_lo >= y_hi) {
            // Nothing of it in the tile: its fans are dropped with it.
            vertices_.resize(vertex_start);
            fan_firsts_.resize(draw.fan_first);
            fan_counts_.resize(draw.fan_first);
            continue;
        }
        draw.cover_first = static_cast<int>(vertices_.size() / 3);
        for (const double y : {y_lo, y_hi}) {
            for (const double x : {x_lo, x_hi}) push(x, y, depth_ndc(shape, x, y, depth_range));
        }
        // Window coordinates are image coordinates minus the tile's origin.
        if (shape.value_plane) {
            const AffinePlane& v = *shape.value_plane;
            draw.plane[0] = static_cast<float>(v.c + v.gx * x0 + v.gy * y0);
            draw.plane[1] = static_cast<float>(v.gx);
            draw.plane[2] = static_cast<float>(v.gy);
        } else {
            draw.plane[0] = static_cast<float>(shape.value);
        }
        shapes_.push_back(draw);
    }
}

void GlContext::draw_tile(const Scene& scene, int samples, int x0, int y0, int tile_w, int tile_h,
                          const double depth_range[2], Image& out) {
    build_tile(scene, x0, y0, tile_w, tile_h, depth_range);
    Target& t = target(samples, tile_w, tile_h);
    const std::size_t bytes = vertices_.size() * sizeof(float);
    if (bytes > vbo_capacity_) {
        vbo_capacity_ = std::max(bytes, 2 * vbo_capacity_);
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vbo_capacity_), nullptr,
                     GL_STREAM_DRAW);
    }
    if (bytes > 0)
        glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(bytes), vertices_.data());

    const bool depth = depth_range[1] > depth_range[0] ||
                       std::any_of(scene.shapes.begin(), scene.shapes.end(),
                                   [](const Shape& s) { return s.inv_depth.has_value(); });
    // The same viewport for every tile (see "Exact vertices"); the scissor keeps the clear,
    // the draws and the resolve to the tile's pixels.
    glViewport(0, 0, kGlTileSidePx, kGlTileSidePx);
    glScissor(0, 0, tile_w, tile_h);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glStencilMask(0xFF);
    glClearColor(static_cast<float>(scene.background), 0.0f, 0.0f, 0.0f);
    glClearDepth(0.0);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_STENCIL_TEST);
    if (samples > 1) {
        glEnable(GL_MULTISAMPLE);
    } else {
        glDisable(GL_MULTISAMPLE);
    }
    for (const ShapeDraw& draw : shapes_) {
        // 1. The winding number of every sample into the stencil.
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glDepthMask(GL_FALSE);
        glDisable(GL_DEPTH_TEST);
        glStencilFunc(GL_ALWAYS, 0, 0xFF);
        glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_INCR_WRAP);
        glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_DECR_WRAP);
        glMultiDrawArrays(GL_TRIANGLE_FAN, fan_firsts_.data() + draw.fan_first,
                          fan_counts_.data() + draw.fan_first, draw.fan_count);
        // 2. The value where it is nonzero (and, in 3-D, nearest), the stencil reset to 0.
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        if (depth) {
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_GEQUAL);
            glDepthMask(GL_TRUE);
        }
        glStencilFunc(GL_NOTEQUAL, 0, 0xFF);
        glStencilOp(GL_KEEP, GL_ZERO, GL_ZERO);
        glUniform3f(plane_location_, draw.plane[0], draw.plane[1], draw.plane[2]);
        glDrawArrays(GL_TRIANGLE_STRIP, draw.cover_first, 4);
    }
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_DEPTH_TEST);
    GLuint read_fbo = t.fbo;
    if (samples > 1) {
        // The resolve: the driver's average of each pixel's samples, in float.
        glBindFramebuffer(GL_READ_FRAMEBUFFER, t.fbo);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, t.resolve_fbo);
        glBlitFramebuffer(0, 0, tile_w, tile_h, 0, 0, tile_w, tile_h, GL_COLOR_BUFFER_BIT,
                          GL_NEAREST);
        read_fbo = t.resolve_fbo;
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, read_fbo);
    glPixelStorei(GL_PACK_ROW_LENGTH, out.width);
    glReadPixels(0, 0, tile_w, tile_h, GL_RED, GL_FLOAT, out.row(y0) + x0);
    if (glGetError() != GL_NO_ERROR)
        throw std::runtime_error("gl-msaa: the driver reported an error");
}

}  // namespace

void gl_draw_rows(const Scene& scene, int samples, Image& out, int row_lo, int row_hi) {
    GlContext& gl = thread_context();
    double depth_range[2];
    scene_depth_range(scene, depth_range);
    for (int y0 = row_lo; y0 < row_hi; y0 += kGlTileSidePx) {
        const int tile_h = std::min(kGlTileSidePx, row_hi - y0);
        for (int x0 = 0; x0 < scene.width; x0 += kGlTileSidePx) {
            const int tile_w = std::min(kGlTileSidePx, scene.width - x0);
            gl.draw_tile(scene, samples, x0, y0, tile_w, tile_h, depth_range, out);
        }
    }
}

std::vector<std::array<double, 2>> gl_sample_positions(int samples) {
    GlContext& gl = thread_context();
    gl.target(samples, 1, 1);
    std::vector<std::array<double, 2>> positions;
    if (samples <= 1) return {{0.5, 0.5}};
    for (int s = 0; s < samples; ++s) {
        GLfloat position[2] = {0.0f, 0.0f};
        glGetMultisamplefv(GL_SAMPLE_POSITION, static_cast<GLuint>(s), position);
        positions.push_back({position[0], position[1]});
    }
    return positions;
}

std::string gl_driver_name() {
    thread_context();
    const auto text = [](GLenum name) {
        const GLubyte* s = glGetString(name);
        return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
    };
    return text(GL_VERSION) + ", " + text(GL_RENDERER);
}

}  // namespace aabench
