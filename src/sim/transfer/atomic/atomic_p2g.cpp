#include "sim/transfer/atomic/atomic_p2g.h"

#include <string>

#include "common/slots.h"

namespace pf {

using gl::ProgramId;

ProgramId AtomicP2g::program(bool apic) const {
    if (sums_ == Sums::floats) return apic ? ProgramId::p2g_apic_float : ProgramId::p2g_float;
    return apic ? ProgramId::p2g_apic : ProgramId::p2g;
}

pf_result AtomicP2g::prepare(const gl::Api&, PassRunner& runner, const P2gGrid& grid, bool apic, const Log& log,
                             const char* fn) {
    if (std::string error = runner.prepare(program(apic)); !error.empty())
        return log.error(PF_ERROR_SHADER_COMPILE, std::string(fn) + ": " + error);
    grid_ = grid;
    return PF_OK;
}

void AtomicP2g::run(PassRunner& runner, const P2gBuffers& in) {
    // The atomics add into both words of every face sample and into every cell's count.
    runner.fill(in.face_accum, uint32_t(grid_.layout.accum_words()), 0u, in.clear);
    runner.fill(in.cell_count, uint32_t(grid_.layout.cells()), 0u, in.clear);
    const Bind pos{PF_SLOT_PARTICLE_POS, &in.positions}, vel{PF_SLOT_PARTICLE_VEL, &in.velocities},
        accum{PF_SLOT_FACE_ACCUM, &in.face_accum}, count{PF_SLOT_CELL_COUNT, &in.cell_count},
        status{PF_SLOT_STATUS, &in.status}, affine{PF_SLOT_PARTICLE_AFFINE, &in.affine};
    runner.run({program(in.apic), in.p2g, in.particles,
                in.apic ? Bindings{pos, vel, accum, count, status, affine} : Bindings{pos, vel, accum, count, status}});
}

}  // namespace pf
