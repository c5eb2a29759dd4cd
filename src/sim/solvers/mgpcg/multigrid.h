// The multigrid V-cycle of MGPCG (McAdams, Sifakis & Teran 2010, "A parallel multigrid
// Poisson solver for fluids simulation on large grids"), as CG's preconditioner: z = V(r).
// Levels halve the grid (rounding up) until one holds at most PF_MG_COARSE_CELLS cells. Coarse
// cell types: AIR if any child is AIR, else FLUID if any child is, else SOLID. Each level
// smooths with red-black Gauss-Seidel (red then black before the coarse correction, black then
// red after it), transfers residuals with R = P^T / 2 and corrections with cell-centred
// trilinear P, and the coarsest level runs symmetric red-black sweeps in one workgroup. Every
// piece is symmetric, so the V-cycle is a symmetric preconditioner, as CG requires.
#pragma once
#include <vector>

#include "sim/solvers/cg/cg_solver.h"

namespace pf {

class Multigrid final : public StoredPreconditioner {
public:
    // Smoothing sweeps (red + black) before and after each coarse correction.
    static constexpr uint32_t kSmoothSweeps = 1;

    std::string init(const gl::Api& gl, PassRunner& runner, SolveControl& control) override;
    void begin(PassRunner& runner, StatId stat, const gl::Buffer& cell_type) override;
    void apply(PassRunner& runner, StatId stat, const gl::Buffer& cell_type, const gl::Buffer& r,
               const gl::Buffer& z) override;

    size_t levels() const { return levels_.size(); }

private:
    struct Level {
        glm::ivec3 dims{0};
        uint32_t cells = 0;
        Indirect record{};
        gl::Buffer type, r, e, tmp;  // level 0 borrows type, r and e from the solve
    };
    // The buffers of level l for this cycle (level 0's come from the caller).
    const gl::Buffer& type_of(size_t l) const { return l == 0 ? *fine_type_ : levels_[l].type; }
    const gl::Buffer& r_of(size_t l) const { return l == 0 ? *fine_r_ : levels_[l].r; }
    const gl::Buffer& e_of(size_t l) const { return l == 0 ? *fine_e_ : levels_[l].e; }
    void smooth(PassRunner& runner, StatId stat, size_t l, bool from_zero, bool red_first);
    void vcycle(PassRunner& runner, StatId stat, size_t l);
    static Uniform coarse_dims(const Level& coarse);

    const SolveControl* control_ = nullptr;
    std::vector<Level> levels_;
    const gl::Buffer* fine_type_ = nullptr;
    const gl::Buffer* fine_r_ = nullptr;
    const gl::Buffer* fine_e_ = nullptr;
};

}  // namespace pf
