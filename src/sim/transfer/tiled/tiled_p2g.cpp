#include "sim/transfer/tiled/tiled_p2g.h"

#include <string>

#include "common/slots.h"
#include "gl/allocation_check.h"

namespace pf {

using gl::ProgramId;

pf_result TiledP2g::prepare(const gl::Api& gl, PassRunner& runner, const P2gGrid& grid, bool apic, const Log& log,
                            const char* fn) {
    for (ProgramId id : {ProgramId::p2g_tile_count, ProgramId::scan_blocks, ProgramId::scan_add, ProgramId::sort_scatter,
                         apic ? ProgramId::p2g_tile_splat_apic : ProgramId::p2g_tile_splat}) {
        if (std::string error = runner.prepare(id); !error.empty())
            return log.error(PF_ERROR_SHADER_COMPILE, std::string(fn) + ": " + error);
    }
    if (tile_slot_.bytes() != 0) return PF_OK;
    const uint64_t tile_count = grid.layout.tiles(PF_P2G_TILE);
    PrefixSum per_tile;
    per_tile.plan(tile_count);
    const uint64_t np = grid.max_particles;
    if (pf_result r = gl::check_storage_block(gl, log, np * 8u, std::string(fn) + ": PF_P2G_TILED needs",
                                              "(8 per particle)", "lower max_particles");
        r != PF_OK)
        return r;
    gl::Buffer tile_slot(gl, size_t(np) * 8, GL_DYNAMIC_COPY, "p2g_tile_slot", gl::Sizing::particles),
        order(gl, size_t(np) * 4, GL_DYNAMIC_COPY, "p2g_tile_order", gl::Sizing::particles);
    per_tile.allocate(gl, "p2g_tile");
    if (pf_result r = gl::check_allocated(
            gl, log,
            std::string(fn) + ": allocating " +
                std::to_string((np * 12 + (per_tile.scan_words() + per_tile.count_words()) * 4) >> 20) +
                " MiB for the tiled P2G");
        r != PF_OK)
        return r;
    grid_ = grid;
    tiles_ = tile_count;
    tile_slot_ = std::move(tile_slot);
    order_ = std::move(order);
    per_tile_ = std::move(per_tile);
    stat_sort_ = runner.add_stat("p2g_tile_sort", PF_PASS_P2G);
    return PF_OK;
}

void TiledP2g::run(PassRunner& r, const P2gBuffers& in) {
    const uint32_t np = in.particles;
    const Bind pos{PF_SLOT_PARTICLE_POS, &in.positions}, tile_slot{PF_SLOT_SORT_CELL_SLOT, &tile_slot_};
    // 1. Count per tile, keeping each particle's tile and slot. The splat adds into the
    // accumulators (cleared) and writes every cell's count (no clear).
    r.fill(in.face_accum, uint32_t(grid_.layout.accum_words()), 0u, in.clear);
    per_tile_.clear_counts(r, in.clear);
    r.run({ProgramId::p2g_tile_count, stat_sort_, np, {pos, {PF_SLOT_SORT_HALF_COUNT, &per_tile_.counts()}, tile_slot}});
    // 2. Tile starts; 3. particle indices grouped by tile.
    per_tile_.run(r, stat_sort_);
    r.run({ProgramId::sort_scatter, stat_sort_, np,
           {tile_slot, {PF_SLOT_SORT_HALF_START, &per_tile_.starts()}, {PF_SLOT_SORT_UNSORTED, &order_}}});
    // 4. One workgroup per tile.
    const Bind vel{PF_SLOT_PARTICLE_VEL, &in.velocities}, start{PF_SLOT_TILE_START, &per_tile_.starts()},
        order{PF_SLOT_TILE_ORDER, &order_}, accum{PF_SLOT_FACE_ACCUM, &in.face_accum},
        count{PF_SLOT_CELL_COUNT, &in.cell_count}, status{PF_SLOT_STATUS, &in.status},
        affine{PF_SLOT_PARTICLE_AFFINE, &in.affine};
    r.run({in.apic ? ProgramId::p2g_tile_splat_apic : ProgramId::p2g_tile_splat, in.p2g, tiles_ * PF_WORKGROUP_SIZE,
           in.apic ? Bindings{pos, vel, start, order, accum, count, status, affine}
                   : Bindings{pos, vel, start, order, accum, count, status}});
}

}  // namespace pf
