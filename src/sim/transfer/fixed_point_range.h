// The fixed-point P2G range (docs/design.md §4.2): PF_P2G_FIXED_POINT's accumulators hold a
// unit weight as 2^(20 - shift) and a velocity of max_speed at the same scale. At 2^20, 2047
// full-weight particles fit a 31-bit sum; a step whose sums overflowed widens the range by 2
// bits for the steps after it, up to 2^10 (2M particles per sample, velocity resolution
// max_speed / 1024 per particle).
#pragma once
#include <cmath>
#include <cstdint>

#include "api/log.h"

namespace pf {

class FixedPointRange {
public:
    static constexpr int kWeightScaleBits = 20;
    // Widest range: 2^(20 - 10) per unit weight.
    static constexpr uint32_t kMaxShift = 10;

    // Fixed-point units of one unit of weight.
    float weight_scale() const { return std::ldexp(1.0f, kWeightScaleBits - int(shift_)); }
    // The readback of step `measured`, taken at the start of step `step`, reports an overflow:
    // widens the range from `step` on, unless that step already ran at a wider range than the
    // one it overflowed or the range is at its widest. Logs a warning and returns true when it
    // widens.
    bool widen_after_overflow(int64_t measured, int64_t step, const Log& log);

    uint32_t shift() const { return shift_; }
    int64_t changed_at_step() const { return changed_at_step_; }
    // A snapshot's range; false (and nothing changed) for a shift beyond kMaxShift.
    bool restore(uint32_t shift, int64_t changed_at_step);

private:
    uint32_t shift_ = 0;
    int64_t changed_at_step_ = 0;  // the range in use from the step after this one
};

}  // namespace pf
