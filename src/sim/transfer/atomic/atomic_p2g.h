// PF_P2G_FIXED_POINT and PF_P2G_FLOAT_ATOMIC: one pass over the particles splats each onto its
// face samples with atomics (shaders/transfer/atomic/p2g.comp), 32-bit fixed-point integers
// (bit-identical run to run, overflow flagged) or floats (no overflow, order-dependent sums).
#pragma once
#include "sim/transfer/p2g_scheme.h"

namespace pf {

class AtomicP2g final : public P2gScheme {
public:
    enum class Sums { fixed_point, floats };
    explicit AtomicP2g(Sums sums) : sums_(sums) {}
    pf_result prepare(const gl::Api& gl, PassRunner& runner, const P2gGrid& grid, bool apic, const Log& log,
                      const char* fn) override;
    void run(PassRunner& runner, const P2gBuffers& in) override;
    bool float_sums() const override { return sums_ == Sums::floats; }

private:
    gl::ProgramId program(bool apic) const;
    Sums sums_;
    P2gGrid grid_{};
};

}  // namespace pf
