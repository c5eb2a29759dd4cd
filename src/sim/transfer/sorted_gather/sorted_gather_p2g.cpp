#include "sim/transfer/sorted_gather/sorted_gather_p2g.h"

#include <algorithm>
#include <string>

#include "common/slots.h"
#include "gl/allocation_check.h"

namespace pf {

using gl::ProgramId;

pf_result SortedGatherP2g::prepare(const gl::Api& gl, PassRunner& runner, const P2gGrid& grid, bool apic,
                                   const Log& log, const char* fn) {
    for (ProgramId id : {ProgramId::p2g_sort_count, ProgramId::scan_blocks, ProgramId::scan_add,
                         ProgramId::sort_scatter, apic ? ProgramId::p2g_sort_rank_apic : ProgramId::p2g_sort_rank,
                         apic ? ProgramId::p2g_gather_apic : ProgramId::p2g_gather}) {
        if (std::string error = runner.prepare(id); !error.empty())
            return log.error(PF_ERROR_SHADER_COMPILE, std::string(fn) + ": " + error);
    }
    if (cell_slot_.bytes() != 0) return PF_OK;
    // Particles are sorted by half cell (2 x 2 x 2 per cell).
    PrefixSum halves;
    halves.plan(grid.layout.half_cells());
    const uint64_t words = halves.scan_words(), np = grid.max_particles;
    const uint64_t largest = std::max<uint64_t>(np * 16u, words * 4u);  // the sorted copies or the starts
    if (pf_result r = gl::check_storage_block(gl, log, largest, std::string(fn) + ": PF_P2G_SORTED_GATHER needs",
                                              "(16 per particle, 32 per cell)", "lower max_particles or the grid size");
        r != PF_OK)
        return r;
    gl::Buffer cell_slot(gl, size_t(np) * 8, GL_DYNAMIC_COPY, "p2g_sort_cell_slot", gl::Sizing::particles),
        unsorted(gl, size_t(np) * 4, GL_DYNAMIC_COPY, "p2g_sort_unsorted", gl::Sizing::particles),
        sorted_grid(gl, size_t(np) * 16, GL_DYNAMIC_COPY, "p2g_sort_grid", gl::Sizing::particles),
        sorted_particles(gl, size_t(np) * 16, GL_DYNAMIC_COPY, "p2g_sort_particles", gl::Sizing::particles);
    halves.allocate(gl, "p2g_sort");
    if (pf_result r = gl::check_allocated(gl, log,
                                          std::string(fn) + ": allocating " +
                                              std::to_string((np * 44 + words * 4 + halves.count_words() * 4) >> 20) +
                                              " MiB for the sorted-gather P2G");
        r != PF_OK)
        return r;
    grid_ = grid;
    cell_slot_ = std::move(cell_slot);
    unsorted_ = std::move(unsorted);
    sorted_grid_ = std::move(sorted_grid);
    sorted_particles_ = std::move(sorted_particles);
    halves_ = std::move(halves);
    stat_sort_ = runner.add_stat("p2g_sort", PF_PASS_P2G);
    stat_gather_ = runner.add_stat("p2g_gather", PF_PASS_P2G);
    return PF_OK;
}

void SortedGatherP2g::run(PassRunner& r, const P2gBuffers& in) {
    const uint32_t np = in.particles;
    const Bind pos{PF_SLOT_PARTICLE_POS, &in.positions}, vel{PF_SLOT_PARTICLE_VEL, &in.velocities},
        count{PF_SLOT_CELL_COUNT, &in.cell_count}, cell_slot{PF_SLOT_SORT_CELL_SLOT, &cell_slot_},
        start{PF_SLOT_SORT_HALF_START, &halves_.starts()}, unsorted{PF_SLOT_SORT_UNSORTED, &unsorted_},
        grid{PF_SLOT_SORT_GRID, &sorted_grid_}, particles{PF_SLOT_SORT_PARTICLE, &sorted_particles_},
        affine{PF_SLOT_PARTICLE_AFFINE, &in.affine};
    // 1. Count per cell and per half cell (both cleared), keeping each particle's half cell and
    // slot. The gather writes every accumulator: they need no clearing.
    r.fill(in.cell_count, uint32_t(grid_.layout.cells()), 0u, in.clear);
    halves_.clear_counts(r, in.clear);
    r.run({ProgramId::p2g_sort_count, stat_sort_, np,
           {pos, count, {PF_SLOT_SORT_HALF_COUNT, &halves_.counts()}, cell_slot}});
    // 2. Half-cell starts: exclusive prefix sum of the counts.
    halves_.run(r, stat_sort_);
    // 3. Indices into their half cells' segments; 4. the fixed order within each half cell, with
    // the particles' grid coordinates, velocities and indices written in that order.
    r.run({ProgramId::sort_scatter, stat_sort_, np, {cell_slot, start, unsorted}});
    r.run({in.apic ? ProgramId::p2g_sort_rank_apic : ProgramId::p2g_sort_rank, stat_sort_, np,
           in.apic ? Bindings{pos, vel, cell_slot, start, unsorted, grid, particles, affine}
                   : Bindings{pos, vel, cell_slot, start, unsorted, grid, particles}});
    // 5. One invocation per face sample sums its particles (both words of every sample).
    const Bind accum{PF_SLOT_FACE_ACCUM, &in.face_accum};
    r.run({in.apic ? ProgramId::p2g_gather_apic : ProgramId::p2g_gather, stat_gather_, grid_.layout.faces(),
           in.apic ? Bindings{start, grid, particles, accum, affine} : Bindings{start, grid, particles, accum}});
}

}  // namespace pf
