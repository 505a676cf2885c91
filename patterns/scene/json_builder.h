// Internal to the scene file reader (scene_io.cpp): pass 1, JSON text -> ordered_json tree,
// with paths for the parser's own errors (scene_io.cpp's opening comment), and the vertices and
// face loops gathered outside the tree (BulkValues, scene_io_detail.h).
#pragma once

#include <fmt/format.h>

#include <climits>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "patterns/scene/scene_io_detail.h"

namespace aabench::scene_io_detail {

// A version-1 scene nests 6 levels (root, shapes, shape, contours, contour, point), a version-2
// one 9 (root, objects, object, faces, face, patterns, pattern, loop, point); anything far
// deeper is not a scene, and stopping early keeps a hostile file from building a deep tree.
// (The message keeps saying 6, the version-1 figure, so version-1 errors stay as they were.)
constexpr std::size_t kMaxNesting = 32;
// What the tree builder reserves for a new array in the tree (see JsonBuilder::open).
constexpr std::size_t kSmallArray = 4;

// --- Pass 1: JSON text -> ordered_json tree, with paths for the parser's own errors ---

class JsonBuilder {
public:
    JsonBuilder(const std::string& source, long long max_vertices)
        : source_(source), max_vertices_(max_vertices) {}

    Json& root() { return root_; }
    const BulkValues& bulk() const { return bulk_; }

    bool null() { return put(Json(nullptr)); }
    bool boolean(bool value) { return put(Json(value)); }
    bool number_integer(Json::number_integer_t value) { return number(value); }
    bool number_unsigned(Json::number_unsigned_t value) { return number(value); }
    bool number_float(Json::number_float_t value, const std::string&) { return number(value); }
    bool string(std::string& value) { return put(Json(std::move(value))); }
    bool binary(Json::binary_t&) { return put(Json(nullptr)); }  // never produced by JSON text

    bool start_object(std::size_t) { return open(/*array=*/false); }
    bool start_array(std::size_t) { return open(/*array=*/true); }
    bool end_object() {
        if (face_.open && face_.has(FaceKey::kLoop) && !face_.value_pending) {
            BulkFace& face = bulk_.faces.emplace_back();
            if (face_.has(FaceKey::kReflectance)) face.reflectance = face_.reflectance.as_double();
            if (face_.has(FaceKey::kMirror)) face.mirror = face_.mirror.as_double();
            face_.open = false;
            return put_placeholder();
        }
        materialize();  // a face without its loop: the reader says so
        return close();
    }
    bool end_array() {
        if (gather_ == Gather::kPoint && pending_count_ == 3) {
            bulk_.points.push_back(
                {pending_[0].as_double(), pending_[1].as_double(), pending_[2].as_double()});
        } else if (gather_ == Gather::kLoop) {
            bulk_.loops.push_back({loop_start_, bulk_.loop_indices.size() - loop_start_});
        } else {
            materialize();  // a point of fewer than three numbers: the reader says so
            return close();
        }
        gather_ = Gather::kNone;
        if (face_.open) {  // the loop of the face being gathered: the face holds its place
            face_.value_pending = false;
            return true;
        }
        return put_placeholder();
    }

    bool key(std::string& key) {
        if (face_.open) {
            // A face's own keys, once each, stay out of the tree; any other key or a repeated
            // one turns the face into a tree object, for the checks below and the reader.
            const std::optional<FaceKey> face_key = face_key_of(key);
            if (face_key && !face_.has(*face_key)) {
                face_.keys[face_.key_count++] = *face_key;
                face_.value_pending = true;
                return true;
            }
            materialize();
        }
        Frame& frame = stack_.back();
        if (frame.node->contains(key)) {
            fail(source_, child_path(container_path(), key),
                 "duplicate key (each key may appear once)");
        }
        frame.key = key;
        return true;
    }

    bool parse_error(std::size_t position, const std::string& last_token,
                     const nlohmann::json::exception& error) {
        materialize();  // so that the path names the element being read
        if (error.id == 406) {
            // out_of_range.406: a number that overflows a double (1e999). JSON has no infinity,
            // and nlohmann refuses to make one; say where it was rather than the byte.
            fail(source_, pending_path(),
                 fmt::format("number {} is not a finite double", printable(last_token)));
        }
        throw InputError(fmt::format("{}: byte {}: invalid JSON ({})", source_, position,
                                     short_reason(error.what())));
    }

private:
    struct Frame {
        Json* node;       // the open container; stable, see slot()
        std::string key;  // objects: the key whose value comes next
    };

    // Where the next value goes. A pointer into the parent stays valid while the child is open
    // because nothing else is added to the parent until the child closes.
    Json* slot() {
        if (stack_.empty()) return &root_;
        Frame& frame = stack_.back();
        if (frame.node->is_array()) {
            frame.node->push_back(nullptr);
            return &frame.node->back();
        }
        return &(*frame.node)[frame.key];
    }

    bool put(Json&& value) {
        materialize();
        *slot() = std::move(value);
        return true;
    }

    // The placeholder of a gathered value (BulkValues), built in place in its array.
    bool put_placeholder() {
        if (!stack_.empty() && stack_.back().node->is_array()) {
            stack_.back().node->get_ref<Json::array_t&>().emplace_back(Json::value_t::discarded);
            return true;
        }
        return put(Json(Json::value_t::discarded));  // a face's loop, in a face in the tree
    }

    // A number as parsed, kept out of the tree until it has to go there: a Json made and
    // destroyed per number cost a tenth of the parse.
    struct ParsedNumber {
        std::variant<Json::number_integer_t, Json::number_unsigned_t, Json::number_float_t> value;
        // As Json's get<double>() gives it.
        double as_double() const {
            return std::visit([](auto v) { return static_cast<double>(v); }, value);
        }
        Json to_json() const {
            return std::visit([](auto v) { return Json(v); }, value);
        }
    };

    // A number goes into the point, loop or face being gathered when it fits there.
    template <typename Number>
    bool number(Number value) {
        if (face_.open && gather_ == Gather::kNone && face_.value_pending &&
            face_.keys[face_.key_count - 1] != FaceKey::kLoop &&
            std::isfinite(static_cast<double>(value))) {
            (face_.keys[face_.key_count - 1] == FaceKey::kReflectance ? face_.reflectance
                                                                      : face_.mirror) =
                ParsedNumber{value};
            face_.value_pending = false;
            return true;
        }
        if (gather_ == Gather::kPoint && pending_count_ < 3) {
            pending_[pending_count_++] = ParsedNumber{value};
            return true;
        }
        // Non-negative integers come as unsigned (nlohmann's rule, kept by the fast parser).
        if constexpr (std::is_same_v<Number, Json::number_unsigned_t>) {
            if (gather_ == Gather::kLoop && value <= static_cast<std::uint64_t>(INT_MAX)) {
                bulk_.loop_indices.push_back(static_cast<int>(value));
                return true;
            }
        }
        return put(Json(value));
    }

    // What is being gathered stops being so: the face becomes the tree's object and the array
    // the tree's array, with what was gathered so far, and parsing goes on as for any value.
    void materialize() {
        if (face_.open) materialize_face();
        if (gather_ == Gather::kNone) return;
        Json array = Json::array();
        if (gather_ == Gather::kPoint) {
            for (int k = 0; k < pending_count_; ++k) array.push_back(pending_[k].to_json());
        } else {
            for (std::size_t k = loop_start_; k < bulk_.loop_indices.size(); ++k) {
                array.push_back(Json(static_cast<Json::number_unsigned_t>(bulk_.loop_indices[k])));
            }
            bulk_.loop_indices.resize(loop_start_);
        }
        gather_ = Gather::kNone;
        Json* node = slot();
        *node = std::move(array);
        stack_.push_back({node, {}});
    }

    // The face object: its keys so far in their order (a finished loop as the placeholder of
    // the loop in `bulk_`), the last one's value still to come when value_pending.
    void materialize_face() {
        face_.open = false;
        Json object = Json::object();
        const int complete = face_.key_count - (face_.value_pending ? 1 : 0);
        for (int k = 0; k < complete; ++k) {
            const FaceKey key = face_.keys[k];
            object[face_key_name(key)] = key == FaceKey::kLoop ? Json(Json::value_t::discarded)
                                         : key == FaceKey::kReflectance
                                             ? face_.reflectance.to_json()
                                             : face_.mirror.to_json();
        }
        Json* node = slot();
        *node = std::move(object);
        stack_.push_back(
            {node, face_.value_pending ? face_key_name(face_.keys[face_.key_count - 1]) : ""});
    }

    // A container opens. It is made only when it goes into the tree: gathered ones (a vertex, a
    // loop, a face) would cost an allocation and a free each for nothing.
    bool open(bool array) {
        if (face_.open && gather_ == Gather::kNone && face_.value_pending &&
            face_.keys[face_.key_count - 1] == FaceKey::kLoop && array) {
            gather_ = Gather::kLoop;  // the face's loop, gathered as any face loop
            loop_start_ = bulk_.loop_indices.size();
            return true;
        }
        materialize();
        if (stack_.size() >= kMaxNesting) {
            fail(source_, pending_path(),
                 fmt::format("nested more than {} levels deep (a scene needs 6)", kMaxNesting));
        }
        const bool point = opens_point();
        if (point && ++points_ > max_vertices_) {
            // Checked as the points stream in, so a hostile file cannot make the tree huge.
            fail(source_, pending_path(),
                 fmt::format("more than {} vertices in the scene (the limit, docs/limits.md)",
                             max_vertices_));
        }
        if (array && point && stack_.size() == 4) {  // objects[o].vertices[v]
            gather_ = Gather::kPoint;
            pending_count_ = 0;
            return true;
        }
        if (!array && opens_face()) {
            face_ = PendingFace{};
            face_.open = true;
            return true;
        }
        if (array && opens_face_loop()) {
            gather_ = Gather::kLoop;
            loop_start_ = bulk_.loop_indices.size();
            return true;
        }
        Json container = array ? Json::array() : Json::object();
        if (array) {
            // Most other arrays of a scene are points of 3 numbers: room for 4 up front makes
            // one allocation where growing from empty made three.
            container.get_ref<Json::array_t&>().reserve(kSmallArray);
        }
        Json* node = slot();
        *node = std::move(container);
        stack_.push_back({node, {}});
        return true;
    }

    bool close() {
        stack_.pop_back();
        return true;
    }

    // The container about to open is a point that counts toward the vertex limit: a 2-D point
    // root.shapes[s].contours[k][p], or (version 2) a 3-D vertex root.objects[o].vertices[v] or
    // a pattern's point root.objects[o].faces[f].patterns[p].loop[k]. The parents' types are
    // checked too, so that `"shapes": {"contours": ...}` and the like do not count.
    bool opens_point() const {
        const auto key_at = [&](std::size_t level, std::string_view key) {
            return stack_[level].node->is_object() && stack_[level].key == key;
        };
        const auto array_at = [&](std::size_t level) { return stack_[level].node->is_array(); };
        switch (stack_.size()) {
            case 5:
                return key_at(0, "shapes") && array_at(1) && key_at(2, "contours") && array_at(3) &&
                       array_at(4);
            case 4:
                return key_at(0, "objects") && array_at(1) && key_at(2, "vertices") && array_at(3);
            case 8:
                return key_at(0, "objects") && array_at(1) && key_at(2, "faces") && array_at(3) &&
                       key_at(4, "patterns") && array_at(5) && key_at(6, "loop") && array_at(7);
            default:
                return false;
        }
    }

    // The container about to open is a face, root.objects[o].faces[f].
    bool opens_face() const {
        const auto key_at = [&](std::size_t level, std::string_view key) {
            return stack_[level].node->is_object() && stack_[level].key == key;
        };
        const auto array_at = [&](std::size_t level) { return stack_[level].node->is_array(); };
        return stack_.size() == 4 && key_at(0, "objects") && array_at(1) && key_at(2, "faces") &&
               array_at(3);
    }

    // The container about to open is a face's loop, root.objects[o].faces[f].loop, of a face
    // in the tree.
    bool opens_face_loop() const {
        const auto key_at = [&](std::size_t level, std::string_view key) {
            return stack_[level].node->is_object() && stack_[level].key == key;
        };
        const auto array_at = [&](std::size_t level) { return stack_[level].node->is_array(); };
        return stack_.size() == 5 && key_at(0, "objects") && array_at(1) && key_at(2, "faces") &&
               array_at(3) && key_at(4, "loop");
    }

    // Path of the innermost open container, rebuilt only when an error needs it.
    std::string container_path() const {
        std::string path;
        for (std::size_t i = 1; i < stack_.size(); ++i) {
            const Frame& parent = stack_[i - 1];
            path = parent.node->is_array() ? child_path(path, parent.node->size() - 1)
                                           : child_path(path, parent.key);
        }
        return path;
    }

    // Path of the value being parsed now (not yet stored).
    std::string pending_path() const {
        if (stack_.empty()) return "";
        const Frame& frame = stack_.back();
        return frame.node->is_array() ? child_path(container_path(), frame.node->size())
                                      : child_path(container_path(), frame.key);
    }

    // nlohmann says "[json.exception.parse_error.101] parse error at line 1, column 6: syntax
    // error while parsing value - unexpected '}'; expected '[', '{', or a literal". Keep from the
    // line onwards: it says what was expected, and the line helps in an editor.
    static std::string short_reason(std::string_view what) {
        constexpr std::string_view kPrefix = "parse error at ";
        if (const auto at = what.find(kPrefix); at != std::string_view::npos) {
            what.remove_prefix(at + kPrefix.size());
        } else if (const auto bracket = what.find("] "); bracket != std::string_view::npos) {
            what.remove_prefix(bracket + 2);
        }
        return printable(what, /*escape_quotes=*/false, std::string_view::npos);
    }

    const std::string& source_;
    Json root_;
    std::vector<Frame> stack_;
    long long max_vertices_;
    long long points_ = 0;
    // The vertex or face loop being gathered into bulk_ rather than the tree (BulkValues).
    enum class Gather { kNone, kPoint, kLoop };
    Gather gather_ = Gather::kNone;
    // kPoint: the numbers so far, as parsed (a message shows them as written)
    ParsedNumber pending_[3];
    int pending_count_ = 0;
    std::size_t loop_start_ = 0;  // kLoop: where its indices start in bulk_.loop_indices
    // The face being gathered into bulk_ rather than the tree (BulkValues, BulkFace).
    enum class FaceKey { kLoop, kReflectance, kMirror };
    static constexpr int kFaceKeys = 3;
    static std::optional<FaceKey> face_key_of(std::string_view key) {
        if (key == "loop") return FaceKey::kLoop;
        if (key == "reflectance") return FaceKey::kReflectance;
        if (key == "mirror") return FaceKey::kMirror;
        return std::nullopt;
    }
    static const char* face_key_name(FaceKey key) {
        return key == FaceKey::kLoop          ? "loop"
               : key == FaceKey::kReflectance ? "reflectance"
                                              : "mirror";
    }
    struct PendingFace {
        bool open = false;
        FaceKey keys[kFaceKeys] = {};  // in the file's order
        int key_count = 0;
        bool value_pending = false;  // the last key's value has not come yet
        ParsedNumber reflectance;    // as parsed (a message shows a number as written)
        ParsedNumber mirror;
        bool has(FaceKey key) const {
            for (int k = 0; k < key_count; ++k) {
                if (keys[k] == key) return true;
            }
            return false;
        }
    };
    PendingFace face_;
    BulkValues bulk_;
};


}  // namespace aabench::scene_io_detail
