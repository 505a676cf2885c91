// The envelope of a fan's sweep (fan_groups.cpp): the outline of the triangles taken so far in
// polar form around the apex, as angular intervals, and the angular buckets that find them.
//
// Why not a balanced tree keyed by angle: the sweep takes the triangles in the input's order,
// at random angles, so every lookup walked ~18 levels of a tree of a few hundred thousand
// nodes with a cache miss at most of them (a third of the sweep's time on 100,000 triangles).
// Here the intervals are a doubly linked list in one array (angular order), and each bucket
// knows the first interval that starts in it, so a lookup is one bucket and a step or two.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "patterns/scene/scene.h"

namespace aabench {

// The interval of angles [lo, hi] (lo is kept by the envelope) is reached farthest by
// `owner`'s chord (-1: by none). Its ends are the rays from the apex through lo_through and
// hi_through (a vertex, a crossing of two chords, or a point on the ray at angle pi).
struct FanInterval {
    double hi = 0.0;
    Point lo_through, hi_through;
    int owner = -1;  // index in the fan's members
};

// `count` equal buckets of angle over [-pi, pi); count a multiple of 64.
struct FanBuckets {
    int count = 64;
    double angle = 2.0 * std::numbers::pi / 64;

    explicit FanBuckets(int n) : count(n), angle(2.0 * std::numbers::pi / n) {}

    // Monotone in a (each step rounds monotonically), so that the buckets of the interval
    // starts are in their angular order.
    int of(double a) const {
        const double b = std::floor((a + std::numbers::pi) / angle);
        return static_cast<int>(std::clamp(b, 0.0, static_cast<double>(count - 1)));
    }
    double start(int b) const {
        return b >= count ? std::numbers::pi : -std::numbers::pi + b * angle;
    }
};

class FanEnvelope {
public:
    static constexpr int kNone = -1;
    struct Node {
        double lo = 0.0;  // where the interval starts
        FanInterval in;
        int prev = kNone, next = kNone;
    };

    // One interval over the whole circle, from -pi (that first node is never erased: the
    // sweep merges a node only into its predecessor, so every lookup finds a start before it).
    FanEnvelope(const FanBuckets& buckets, const FanInterval& whole)
        : buckets_(buckets),
          head_(static_cast<std::size_t>(buckets.count), kNone),
          nonempty_(static_cast<std::size_t>(buckets.count) / 64, 0) {
        const int n = make(-std::numbers::pi, whole);
        set_head(0, n);
    }

    // Node references are good until the next insert_after (the array may grow).
    Node& operator[](int n) { return nodes_[static_cast<std::size_t>(n)]; }
    const Node& operator[](int n) const { return nodes_[static_cast<std::size_t>(n)]; }

    // The interval holding angle a >= -pi: the last one that starts at or before it.
    int locate(double a) const {
        const int b = buckets_.of(a);
        int n = head_[static_cast<std::size_t>(b)];
        if (n == kNone || (*this)[n].lo > a) n = head_[static_cast<std::size_t>(before(b))];
        for (int m = (*this)[n].next; m != kNone && (*this)[m].lo <= a; m = (*this)[m].next) {
            n = m;
        }
        return n;
    }

    // A new interval starting at lo, right after n (n's start < lo < the start of n's next).
    int insert_after(int n, double lo, const FanInterval& in) {
        const int m = make(lo, in);
        const int after = (*this)[n].next;
        (*this)[m].prev = n;
        (*this)[m].next = after;
        (*this)[n].next = m;
        if (after != kNone) (*this)[after].prev = m;
        const int b = buckets_.of(lo);
        const int head = head_[static_cast<std::size_t>(b)];
        if (head == kNone || (*this)[head].lo > lo) set_head(b, m);
        return m;
    }

    void erase(int n) {
        const int p = (*this)[n].prev, q = (*this)[n].next;
        if (p != kNone) (*this)[p].next = q;
        if (q != kNone) (*this)[q].prev = p;
        const int b = buckets_.of((*this)[n].lo);
        if (head_[static_cast<std::size_t>(b)] == n) {
            if (q != kNone && buckets_.of((*this)[q].lo) == b) {
                head_[static_cast<std::size_t>(b)] = q;
            } else {
                head_[static_cast<std::size_t>(b)] = kNone;
                nonempty_[static_cast<std::size_t>(b / 64)] &= ~(std::uint64_t{1} << (b % 64));
            }
        }
        free_.push_back(n);
    }

private:
    int make(double lo, const FanInterval& in) {
        if (free_.empty()) {
            nodes_.push_back(Node{lo, in});
            return static_cast<int>(nodes_.size() - 1);
        }
        const int n = free_.back();
        free_.pop_back();
        (*this)[n] = Node{lo, in};
        return n;
    }

    void set_head(int b, int n) {
        head_[static_cast<std::size_t>(b)] = n;
        nonempty_[static_cast<std::size_t>(b / 64)] |= std::uint64_t{1} << (b % 64);
    }

    // The nearest bucket before b that holds an interval start (bucket 0 always does).
    int before(int b) const {
        int w = b / 64;
        std::uint64_t bits =
            nonempty_[static_cast<std::size_t>(w)] & ((std::uint64_t{1} << (b % 64)) - 1);
        while (bits == 0) bits = nonempty_[static_cast<std::size_t>(--w)];
        return w * 64 + 63 - std::countl_zero(bits);
    }

    FanBuckets buckets_;
    std::vector<Node> nodes_;
    std::vector<int> free_;                // erased nodes, reused
    std::vector<int> head_;                // per bucket: its first interval start, kNone for none
    std::vector<std::uint64_t> nonempty_;  // per bucket: a bit, set when head_ is not kNone
};

}  // namespace aabench
