// The multigrid V-cycle of cpu_reference.h, written for clarity: whole-level loops, no fusion.
#include <algorithm>

#include "reference/cpu_reference.h"

namespace pf::ref {
namespace {

struct Level {
    glm::ivec3 n{0};
    std::vector<uint8_t> type;
    std::vector<double> extra;  // the surface term of the diagonal (fine level only)
    int cells() const { return n.x * n.y * n.z; }
    int index(glm::ivec3 q) const { return q.x + n.x * (q.y + n.y * q.z); }
    bool inside(glm::ivec3 q) const { return glm::all(glm::greaterThanEqual(q, glm::ivec3(0))) && glm::all(glm::lessThan(q, n)); }
    glm::ivec3 coord(int c) const { return {c % n.x, (c / n.x) % n.y, c / (n.x * n.y)}; }
};

const glm::ivec3 kFaces[6] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};

// diag and the sum of FLUID neighbours' e at FLUID cell c.
void stencil(const Level& L, const std::vector<double>& e, int c, double& diag, double& sum) {
    diag = L.extra.empty() ? 0.0 : L.extra[size_t(c)];
    sum = 0.0;
    const glm::ivec3 q = L.coord(c);
    for (const glm::ivec3& d : kFaces) {
        if (!L.inside(q + d)) continue;
        const int nb = L.index(q + d);
        if (L.type[size_t(nb)] == SOLID) continue;
        diag += 1.0;
        if (L.type[size_t(nb)] == FLUID) sum += e[size_t(nb)];
    }
}

void sweep(const Level& L, const std::vector<double>& r, std::vector<double>& e, int color) {
    for (int c = 0; c < L.cells(); ++c) {
        const glm::ivec3 q = L.coord(c);
        if (((q.x + q.y + q.z) & 1) != color || L.type[size_t(c)] != FLUID) continue;
        double diag, sum;
        stencil(L, e, c, diag, sum);
        e[size_t(c)] = diag > 0.0 ? (r[size_t(c)] + sum) / diag : 0.0;
    }
}

std::vector<double> cycle(const std::vector<Level>& levels, size_t l, const std::vector<double>& r, int coarse_sweeps) {
    const Level& L = levels[l];
    std::vector<double> e(size_t(L.cells()), 0.0);
    sweep(L, r, e, 0);
    if (l + 1 == levels.size()) {
        for (int k = 0; k < coarse_sweeps; ++k) {
            sweep(L, r, e, 1);
            sweep(L, r, e, 0);
        }
        return e;
    }
    sweep(L, r, e, 1);
    std::vector<double> res(size_t(L.cells()), 0.0);
    for (int c = 0; c < L.cells(); ++c) {
        if (L.type[size_t(c)] != FLUID) continue;
        double diag, sum;
        stencil(L, e, c, diag, sum);
        res[size_t(c)] = r[size_t(c)] - (diag * e[size_t(c)] - sum);
    }
    const Level& C = levels[l + 1];
    const glm::ivec3 coarsened = glm::ivec3(glm::lessThan(C.n, L.n));
    const double scale = 4.0 / double(1 << (coarsened.x + coarsened.y + coarsened.z));
    std::vector<double> rc(size_t(C.cells()), 0.0);
    for (int cc = 0; cc < C.cells(); ++cc) {
        if (C.type[size_t(cc)] != FLUID) continue;
        const glm::ivec3 q = C.coord(cc);
        double sum = 0.0;
        for (int dz = -1; dz <= 2; ++dz)
            for (int dy = -1; dy <= 2; ++dy)
                for (int dx = -1; dx <= 2; ++dx) {
                    const glm::ivec3 f = 2 * q + glm::ivec3(dx, dy, dz);
                    if (!L.inside(f)) continue;
                    sum += prolong_weight(f.x, q.x, C.n.x) * prolong_weight(f.y, q.y, C.n.y) *
                           prolong_weight(f.z, q.z, C.n.z) * res[size_t(L.index(f))];
                }
        rc[size_t(cc)] = scale * sum;
    }
    const std::vector<double> ec = cycle(levels, l + 1, rc, coarse_sweeps);
    for (int c = 0; c < L.cells(); ++c) {
        if (L.type[size_t(c)] != FLUID) continue;
        const glm::ivec3 f = L.coord(c);
        for (int n = 0; n < 8; ++n) {
            const glm::ivec3 pick(n & 1, (n >> 1) & 1, (n >> 2) & 1);
            const glm::ivec3 parent = f >> 1;
            const glm::ivec3 other = glm::clamp(parent + 2 * (f & 1) - 1, glm::ivec3(0), C.n - 1);
            const glm::ivec3 q = parent + pick * (other - parent);
            const glm::dvec3 w = glm::dvec3(0.75) - 0.5 * glm::dvec3(pick);
            e[size_t(c)] += w.x * w.y * w.z * ec[size_t(C.index(q))];
        }
    }
    sweep(L, r, e, 1);
    sweep(L, r, e, 0);
    return e;
}

}  // namespace

double prolong_weight(int f, int c, int nc) {
    const int parent = f >> 1;
    const int other = std::clamp((f & 1) == 0 ? parent - 1 : parent + 1, 0, nc - 1);
    return (parent == c ? 0.75 : 0.0) + (other == c ? 0.25 : 0.0);
}

std::vector<double> multigrid_vcycle(const Grid& grid, const std::vector<uint8_t>& type,
                                     const std::vector<double>& extra_diagonal, const std::vector<double>& r,
                                     int coarse_cells, int max_levels, int coarse_sweeps) {
    std::vector<Level> levels;
    levels.push_back(Level{grid.cell_dims(), type, extra_diagonal});
    while (levels.back().cells() > coarse_cells && int(levels.size()) < max_levels) {
        const Level& F = levels.back();
        Level C;
        C.n = (F.n + 1) / 2;
        C.type.assign(size_t(C.cells()), SOLID);
        for (int cc = 0; cc < C.cells(); ++cc) {
            bool air = false, fluid = false;
            for (int n = 0; n < 8; ++n) {
                const glm::ivec3 f = 2 * C.coord(cc) + glm::ivec3(n & 1, (n >> 1) & 1, (n >> 2) & 1);
                if (!F.inside(f)) continue;
                air = air || F.type[size_t(F.index(f))] == AIR;
                fluid = fluid || F.type[size_t(F.index(f))] == FLUID;
            }
            C.type[size_t(cc)] = air ? AIR : fluid ? FLUID : SOLID;
        }
        levels.push_back(std::move(C));
    }
    return cycle(levels, 0, r, coarse_sweeps);
}

}  // namespace pf::ref
