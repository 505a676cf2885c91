// A scene as its producer hands it to a method or a reference, with what the producer knows of
// its shapes that the scene itself does not say.
//
// Two facts. Exact visibility (harness/reference/visibility.h) returns disjoint
// convex pieces, constant-valued. The box reference then integrates them as they are, where
// resolving them again would find nothing to cut at the cost of testing every pair of touching
// pieces (minutes for the 250,000 pieces of a 200,000-triangle soup), and `exact` sums pieces
// more numerous than pixels one by one (methods/scan/exact/exact_image.h). The knowledge travels
// beside the scene, not in it: whoever copies or edits a Scene makes a plain scene, so no code
// that adds a shape can leave a stale promise behind. The prepared frame (harness/world/frame.h)
// is what hands out disjoint pieces. And a colour scene's channels, each as a grey scene, made
// once beside it (with_channels).
//
// A view: it refers to a scene that must outlive it (a function argument, or the frame's own).
#pragma once

#include <array>
#include <optional>

#include "patterns/scene/scene.h"

namespace aabench {

class SceneInput {
public:
    // A scene known to be nothing more than what it says (implicit: every Scene is one).
    SceneInput(const Scene& scene) : scene_(&scene) {}  // NOLINT(google-explicit-constructor)
    // `pieces`, known to be disjoint convex constant-valued pieces (visible_pieces' output).
    static SceneInput disjoint_pieces(const Scene& pieces) {
        SceneInput in(pieces);
        in.disjoint_ = true;
        return in;
    }

    // `other` known to be what this one is: for the same shapes moved or revalued (pieces
    // stay disjoint pieces when every piece moves alike or takes another value).
    SceneInput same_kind(const Scene& other) const {
        SceneInput in(other);
        in.disjoint_ = disjoint_;
        return in;
    }

    const Scene& scene() const { return *scene_; }
    bool is_disjoint_pieces() const { return disjoint_; }

    // A colour scene's three channels as grey scenes (channel_scene), made once by whoever holds
    // the scene (the prepared frame), so that a method drawing channel by channel allocates
    // nothing per render. They must outlive the view, as the scene does.
    SceneInput with_channels(const std::array<Scene, 3>& channels) const {
        SceneInput in = *this;
        in.channels_ = &channels;
        return in;
    }
    // Channel c's grey scene when made (with_channels), else nullptr.
    const Scene* channel(int c) const {
        return channels_ ? &(*channels_)[static_cast<std::size_t>(c)] : nullptr;
    }

private:
    const Scene* scene_;
    bool disjoint_ = false;
    const std::array<Scene, 3>* channels_ = nullptr;
};

// Channel c of `in`'s colour scene as a grey input of the same kind: the channel scene made
// beside it (with_channels), or else channel_scene made into `storage`, which must outlive the
// view.
inline SceneInput channel_input(const SceneInput& in, int c, std::optional<Scene>& storage) {
    if (const Scene* made = in.channel(c)) return in.same_kind(*made);
    storage = channel_scene(in.scene(), c);
    return in.same_kind(*storage);
}

}  // namespace aabench
