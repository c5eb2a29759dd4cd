// The exclusive prefix sum of a counting sort's counts (shaders/transfer/common/scan_blocks.comp
// and scan_add.comp), shared by the P2G schemes that sort particles by a key: the counts of
// `items` keys and one zero after them, so that start[k + 1] - start[k] is the count of every k.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "gl/buffer.h"
#include "gl/gl.h"
#include "sim/pass_runner.h"

namespace pf {

class PrefixSum {
public:
    // Plans the levels for `keys` keys (scan_words() is then known), then allocates the count and
    // the scan buffers (no GL error check: the caller checks after all its allocations). `what`
    // names them ("<what>_counts", "<what>_scan").
    void plan(uint64_t keys);
    void allocate(const gl::Api& gl, const char* what);
    // Words of the scan buffer and of the count buffer (the allocation's size).
    uint64_t scan_words() const { return scan_words_; }
    uint64_t count_words() const { return levels_.empty() ? 0 : levels_[0].count; }
    // Per key (plus one): the particles counted (cleared by clear_counts, added to by the
    // counting pass) and, after run, the first index of its particles in the sorted order.
    const gl::Buffer& counts() const { return counts_; }
    const gl::Buffer& starts() const { return scan_; }
    void clear_counts(PassRunner& runner, StatId stat) const;
    // Records the scan: up the levels, then back down.
    void run(PassRunner& runner, StatId stat) const;

private:
    // One level: its items and the word offsets of its input, its prefixes and its block totals.
    struct Level {
        uint32_t count = 0, in = 0, out = 0, sums = 0;
    };
    std::vector<Level> levels_;
    uint64_t scan_words_ = 0;
    gl::Buffer counts_, scan_;
};

}  // namespace pf
