#include "sim/transfer/fixed_point_range.h"

#include <string>

namespace pf {

bool FixedPointRange::widen_after_overflow(int64_t measured, int64_t step, const Log& log) {
    // An overflow of a step run before the last widening says nothing about today's range.
    if (measured <= changed_at_step_ || shift_ >= kMaxShift) return false;
    shift_ += 2;
    changed_at_step_ = step - 1;
    log.warning("pf_step: fixed-point particle-to-grid range widened to " + std::to_string((1u << (11 + shift_)) - 1) +
                " full-weight particles per grid sample (velocity resolution max_speed / 2^" +
                std::to_string(kWeightScaleBits - int(shift_)) + ")");
    return true;
}

bool FixedPointRange::restore(uint32_t shift, int64_t changed_at_step) {
    if (shift > kMaxShift) return false;
    shift_ = shift;
    changed_at_step_ = changed_at_step;
    return true;
}

}  // namespace pf
