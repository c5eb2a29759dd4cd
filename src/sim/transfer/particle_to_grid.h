// Particle-to-grid, the simulation's side: the scheme pf_sim_params.p2g selects (each made and
// prepared on first use, kept after, so switching back costs nothing), the fixed-point range
// they share, and the "p2g" statistics entry.
#pragma once
#include <memory>

#include "sim/transfer/fixed_point_range.h"
#include "sim/transfer/p2g_scheme.h"

namespace pf {

class ParticleToGrid {
public:
    // Registers the "p2g" statistics entry (the caller keeps the core entries' order).
    void init(PassRunner& runner, const P2gGrid& grid);
    // Makes and prepares the scheme `params` select (APIC's programs with an APIC transfer).
    // Errors are logged (prefixed with `fn`) and returned; the running scheme is untouched then.
    pf_result prepare(const gl::Api& gl, PassRunner& runner, const pf_sim_params& params, const Log& log,
                      const char* fn);
    // Records one substep's transfer with the scheme `params` select (prepared).
    void run(PassRunner& runner, const pf_sim_params& params, P2gBuffers in);
    // Whether that scheme's accumulators hold floats (prepared).
    bool float_sums(const pf_sim_params& params) const { return schemes_[params.p2g]->float_sums(); }
    // That scheme's particle order (P2gScheme::particle_order), if it has one (prepared).
    const gl::Buffer* particle_order(const pf_sim_params& params) const { return schemes_[params.p2g]->particle_order(); }
    // Whether that scheme is prepared and makes such an order.
    bool has_particle_order(const pf_sim_params& params) const {
        return schemes_[params.p2g] && schemes_[params.p2g]->particle_order();
    }

    FixedPointRange& range() { return range_; }
    const FixedPointRange& range() const { return range_; }

private:
    P2gGrid grid_{};
    StatId stat_ = 0;
    std::unique_ptr<P2gScheme> schemes_[PF_P2G_COUNT];
    FixedPointRange range_;
};

}  // namespace pf
