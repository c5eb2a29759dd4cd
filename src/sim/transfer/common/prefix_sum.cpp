#include "sim/transfer/common/prefix_sum.h"

#include "common/slots.h"

namespace pf {

using gl::ProgramId;

void PrefixSum::plan(uint64_t keys) {
    // The counts and one zero after them, then their totals per block of PF_SCAN_BLOCK, and so on
    // until one workgroup scans them all. One buffer: the starts (level 0's prefixes) at word 0,
    // then per level above its block totals and their prefixes, then the grand total.
    const uint64_t items = keys + 1u;
    std::vector<Level> levels{Level{uint32_t(items), 0, 0, 0}};
    uint64_t words = items;
    while (levels.back().count > PF_SCAN_BLOCK) {
        const uint32_t blocks = (levels.back().count + PF_SCAN_BLOCK - 1) / PF_SCAN_BLOCK;
        levels.back().sums = uint32_t(words);
        levels.push_back(Level{blocks, uint32_t(words), uint32_t(words + blocks), 0});
        words += 2u * blocks;
    }
    levels.back().sums = uint32_t(words);
    words += 1;
    levels_ = std::move(levels);
    scan_words_ = words;
}

void PrefixSum::allocate(const gl::Api& gl, const char* what) {
    counts_ = gl::Buffer(gl, size_t(count_words()) * 4, GL_DYNAMIC_COPY, (std::string(what) + "_counts").c_str());
    scan_ = gl::Buffer(gl, size_t(scan_words_) * 4, GL_DYNAMIC_COPY, (std::string(what) + "_scan").c_str());
}

void PrefixSum::clear_counts(PassRunner& runner, StatId stat) const {
    runner.fill(counts_, levels_[0].count, 0u, stat);
}

void PrefixSum::run(PassRunner& r, StatId stat) const {
    for (size_t k = 0; k < levels_.size(); ++k) {
        const Level& l = levels_[k];
        const uint64_t invocations = (uint64_t(l.count) + PF_SCAN_ITEMS_PER_INVOCATION - 1) / PF_SCAN_ITEMS_PER_INVOCATION;
        r.run({ProgramId::scan_blocks, stat, invocations,
               {{PF_SLOT_SCAN_IN, k == 0 ? &counts_ : &scan_}, {PF_SLOT_SCAN_OUT, &scan_}}, {},
               {Uniform::uint1(PF_LOC_SCAN_COUNT, l.count), Uniform::uint1(PF_LOC_SCAN_IN_OFFSET, l.in),
                Uniform::uint1(PF_LOC_SCAN_OUT_OFFSET, l.out), Uniform::uint1(PF_LOC_SCAN_SUMS_OFFSET, l.sums)}});
    }
    for (size_t k = levels_.size() - 1; k-- > 0;) {
        const Level& l = levels_[k];
        r.run({ProgramId::scan_add, stat, l.count, {{PF_SLOT_SCAN_OUT, &scan_}}, {},
               {Uniform::uint1(PF_LOC_SCAN_COUNT, l.count), Uniform::uint1(PF_LOC_SCAN_OUT_OFFSET, l.out),
                Uniform::uint1(PF_LOC_SCAN_SUMS_OFFSET, levels_[k + 1].out)}});
    }
}

}  // namespace pf
