#include "sim/transfer/particle_to_grid.h"

#include <string>

namespace pf {

void ParticleToGrid::init(PassRunner& runner, const P2gGrid& grid) {
    grid_ = grid;
    stat_ = runner.add_stat("p2g", PF_PASS_P2G);
}

pf_result ParticleToGrid::prepare(const gl::Api& gl, PassRunner& runner, const pf_sim_params& params, const Log& log,
                                  const char* fn) {
    std::unique_ptr<P2gScheme>& slot = schemes_[params.p2g];
    std::unique_ptr<P2gScheme> made;
    if (!slot) {
        made = make_p2g_scheme(params.p2g);
        if (!made) return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": unknown particle-to-grid scheme");
    }
    P2gScheme& scheme = slot ? *slot : *made;
    if (pf_result r = scheme.prepare(gl, runner, grid_, params.transfer == PF_TRANSFER_APIC, log, fn); r != PF_OK)
        return r;
    if (made) slot = std::move(made);
    return PF_OK;
}

void ParticleToGrid::run(PassRunner& runner, const pf_sim_params& params, P2gBuffers in) {
    in.p2g = stat_;
    schemes_[params.p2g]->run(runner, in);
}

}  // namespace pf
