// The multigrid V-cycle of MGPCG (McAdams, Sifakis & Teran 2010, "A parallel multigrid
// Poisson solver for fluids simulation on large grids"), as CG's preconditioner: z = V(r).
// Levels halve the grid (rounding up; an axis of one cell stays one) until one holds at most
// PF_MG_COARSE_CELLS cells, so flat and thin grids (a 2.5D tank of 256x128x2) coarsen too. Coarse
// cell types: AIR if any child is AIR, else FLUID if any child is, else SOLID. Each level
// smooths with one red-black Gauss-Seidel sweep from zero before the coarse correction (red,
// black) and one after it (black, red), transfers residuals with R = P^T / 2 (the Galerkin scale
// 4 / 2^d for d coarsened axes: 1 on a flat grid, mg_down.comp) and corrections with
// cell-centred trilinear P, and the coarsest level runs symmetric red-black sweeps in one
// workgroup. Every piece is symmetric, so the V-cycle is a symmetric preconditioner, as CG
// requires.
//
// Passes per level (docs/design.md §4.6): the first red half-sweep needs only the cell's own r,
// so it is done by the pass that makes r (CG's update on the fine grid, the restriction on
// coarser ones). A coarse level of at most PF_MG_FUSED_CELLS cells then takes one pass down (the
// black half-sweep, the residual and its restriction: mg_down.comp) and one up (the coarse
// correction, black and red: mg_up.comp), working on tiles with their halos in shared memory.
// The fine level and larger ones, where a tile's repeated halo work costs more than a launch,
// take five: the black half-sweep, the residual (mg_residual.comp), the restriction
// (mg_restrict.comp), the correction with the black half-sweep (mg_prolong_smooth.comp) and the
// red one. The fine
// level's last red half-sweep carries CG's sums of z (mg_smooth_zstats.comp). On the H100 each
// pass costs a few microseconds of launch and barrier whatever its size, so the level above the
// coarsest, when it is not the fine one and has at most PF_MG_BOTTOM_CELLS cells, runs its way
// down, the coarsest level's sweeps and its way up in one workgroup (mg_bottom.comp): one
// dispatch for three. A pair solve's V-cycle (two problems' values a cell, SolveControl) takes
// the fused passes there instead: the bottom's shared memory would not hold two values a cell.
//
// With Galerkin coarse levels (shaders/solvers/mgpcg/galerkin.glsl) every level below the fine
// one stores its operator, made once a solve from the finer one's (begin()), and takes one pass
// down (Jacobi from zero, residual, aggregation: mg_galerkin_down.comp) and one up
// (mg_galerkin_up.comp); the coarsest, at least level 2, takes mg_galerkin_coarse.comp.
#pragma once
#include <vector>

#include "sim/solvers/cg/cg_solver.h"

namespace pf {

class Multigrid final : public StoredPreconditioner {
public:
    // How the coarse levels get their operator: rebuilt from coarsened cell types, or the Galerkin product.
    enum class Coarse { geometric, galerkin };
    explicit Multigrid(Coarse coarse) : galerkin_(coarse == Coarse::galerkin) {}

    std::string init(const gl::Api& gl, PassRunner& runner, SolveControl& control) override;
    void begin(PassRunner& runner, StatId stat, const gl::Buffer& cell_type) override;
    const gl::Buffer& first_sweep() const override { return start_; }
    void apply(PassRunner& runner, StatId stat, const gl::Buffer& cell_type, const gl::Buffer& r, const gl::Buffer& z,
               bool first_sweep_done, uint32_t cg_step, bool pair) override;

    size_t levels() const { return levels_.size(); }

private:
    struct Level {
        glm::ivec3 dims{0};
        uint32_t cells = 0;
        bool fused = false;     // small enough for the fused kernels (PF_MG_FUSED_CELLS)
        bool bottom = false;    // the level above the coarsest, both in one workgroup (mg_bottom.comp)
        Indirect record{};      // the level's cells (the fine level's, or an unfused pass's)
        Indirect down{}, up{};  // a fused level's mg_down (over the next level's tiles) and mg_up (a bottom
                                // level's too, for a pair's cycle)
        // type, r: the level's system; e: the correction while pre-smoothing; out: the residual
        // after pre-smoothing, then the level's result (the coarsest level: only its result).
        // Level 0 borrows type, r and out (= z) from the solve; its e is start_.
        gl::Buffer type, r, e, out;
        gl::Buffer stencil;     // a Galerkin level's operator (5^3 coefficients a cell on level 1, 3^3 deeper)
        Indirect down_cells{};  // a Galerkin level's way down: 8 invocations per cell of the next level
    };
    // The buffers of level l for this cycle (level 0's come from the caller).
    const gl::Buffer& type_of(size_t l) const { return l == 0 ? *fine_type_ : levels_[l].type; }
    const gl::Buffer& r_of(size_t l) const { return l == 0 ? *fine_r_ : levels_[l].r; }
    const gl::Buffer& e_of(size_t l) const { return l == 0 ? start_ : levels_[l].e; }
    const gl::Buffer& out_of(size_t l) const { return l == 0 ? *fine_z_ : levels_[l].out; }
    bool coarsest(size_t l) const { return l + 1 == levels_.size(); }
    // Level l runs mg_bottom.comp in this cycle (never in a pair's).
    bool bottom(size_t l) const { return levels_[l].bottom && !pair_; }
    // Kernel `id` for this cycle (a pair's permutation in a pair's).
    gl::ProgramId program(gl::ProgramId id) const { return control_->program(id, pair_); }
    void vcycle(PassRunner& runner, StatId stat, size_t l, uint32_t cg_step);
    // A Galerkin level's part of the V-cycle (l >= 1): down, the coarser levels, up.
    void galerkin_vcycle(PassRunner& runner, StatId stat, size_t l);
    // One colour of a Gauss-Seidel sweep on an unfused level l's buffer x.
    void half_sweep(PassRunner& runner, StatId stat, size_t l, const gl::Buffer& x, uint32_t color);
    static Uniform coarse_dims(const Level& coarse);

    const SolveControl* control_ = nullptr;
    std::vector<Level> levels_;
    gl::Buffer start_;  // level 0's e: the first red half-sweep, written by CG's update
    const gl::Buffer* fine_type_ = nullptr;
    const gl::Buffer* fine_r_ = nullptr;
    const gl::Buffer* fine_z_ = nullptr;
    bool pair_ = false;  // this cycle's
    const bool galerkin_;  // Galerkin coarse levels
};

}  // namespace pf
