// The Galerkin multigrid V-cycle of cpu_reference.h, written for clarity: the coarse operators
// are built as explicit sparse matrices (A_coarse = R A P with P and R as matrices), not as the
// GPU's per-entry gathers.
#include <algorithm>
#include <map>

#include "reference/cpu_reference.h"

namespace pf::ref {
namespace {

using Row = std::map<int, double>;  // column -> coefficient
using Matrix = std::vector<Row>;

struct Level {
    glm::ivec3 n{0};
    std::vector<uint8_t> type;  // the fine level's types; FLUID (active) or not on coarser ones
    Matrix A;                   // rows of cells that are not FLUID are empty
    int cells() const { return n.x * n.y * n.z; }
    int index(glm::ivec3 q) const { return q.x + n.x * (q.y + n.y * q.z); }
    bool inside(glm::ivec3 q) const { return glm::all(glm::greaterThanEqual(q, glm::ivec3(0))) && glm::all(glm::lessThan(q, n)); }
    glm::ivec3 coord(int c) const { return {c % n.x, (c / n.x) % n.y, c / (n.x * n.y)}; }
};

const glm::ivec3 kFaces[6] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};

// P as rows of the fine level (FLUID rows only), columns of the coarse level's FLUID cells.
Matrix prolongation(const Level& F, const Level& C, bool first) {
    Matrix P(size_t(F.cells()));
    const glm::ivec3 coarsened = glm::ivec3(glm::lessThan(C.n, F.n));
    for (int f = 0; f < F.cells(); ++f) {
        if (F.type[size_t(f)] != FLUID) continue;
        const glm::ivec3 q = F.coord(f);
        if (!first) {  // aggregation: the parent's value
            const glm::ivec3 parent(q.x >> coarsened.x, q.y >> coarsened.y, q.z >> coarsened.z);
            P[size_t(f)][C.index(parent)] = 1.0;
            continue;
        }
        // The coarse cells P can reach from f: per axis its parent and the parent's other neighbour.
        const glm::ivec3 parent = q >> 1;
        const glm::ivec3 lo = glm::max(parent - 1, glm::ivec3(0)), hi = glm::min(parent + 1, C.n - 1);
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x) {
                    const int c = C.index({x, y, z});
                    if (C.type[size_t(c)] != FLUID) continue;
                    const double w = prolong_weight(q.x, x, C.n.x) * prolong_weight(q.y, y, C.n.y) * prolong_weight(q.z, z, C.n.z);
                    if (w != 0.0) P[size_t(f)][c] = w;
                }
    }
    return P;
}

// s P^T A P.
Matrix galerkin(const Matrix& A, const Matrix& P, int coarse_cells, double s) {
    Matrix AP(A.size());
    for (size_t i = 0; i < A.size(); ++i)
        for (const auto& [j, a] : A[i])
            for (const auto& [c, p] : P[size_t(j)]) AP[i][c] += a * p;
    Matrix out(static_cast<size_t>(coarse_cells));
    for (size_t i = 0; i < P.size(); ++i)
        for (const auto& [c, p] : P[i])
            for (const auto& [d, ap] : AP[i]) out[size_t(c)][d] += s * p * ap;
    return out;
}

std::vector<double> multiply(const Matrix& A, const std::vector<double>& x) {
    std::vector<double> y(A.size(), 0.0);
    for (size_t i = 0; i < A.size(); ++i)
        for (const auto& [j, a] : A[i]) y[i] += a * x[size_t(j)];
    return y;
}

double diagonal(const Row& row, int i) {
    const auto it = row.find(i);
    return it == row.end() ? 0.0 : it->second;
}

// Gauss-Seidel on the cells of one colour: x_i += (r - A x)_i / A_ii.
void relax(const Level& L, const std::vector<double>& r, std::vector<double>& x, int color, int colors) {
    for (int c = 0; c < L.cells(); ++c) {
        const glm::ivec3 q = L.coord(c);
        const int k = colors == 2 ? (q.x + q.y + q.z) & 1 : (q.x & 1) + 2 * (q.y & 1) + 4 * (q.z & 1);
        const double d = diagonal(L.A[size_t(c)], c);
        if (k != color || d <= 0.0) continue;
        double ax = 0.0;
        for (const auto& [j, a] : L.A[size_t(c)]) ax += a * x[size_t(j)];
        x[size_t(c)] += (r[size_t(c)] - ax) / d;
    }
}

struct Hierarchy {
    std::vector<Level> levels;
    std::vector<Matrix> P;  // P[l]: level l+1 onto level l
    std::vector<double> scale;
};

std::vector<double> cycle(const Hierarchy& h, size_t l, const std::vector<double>& r, const GalerkinCycle& k) {
    const Level& L = h.levels[l];
    std::vector<double> e(size_t(L.cells()), 0.0);
    if (l + 1 == h.levels.size()) {
        for (int s = 0; s < k.coarse_pairs; ++s) {
            for (int c = 0; c < 8; ++c) relax(L, r, e, c, 8);
            for (int c = 7; c >= 0; --c) relax(L, r, e, c, 8);
        }
        return e;
    }
    if (l == 0) {
        relax(L, r, e, 0, 2);
        relax(L, r, e, 1, 2);
    } else {
        for (int c = 0; c < L.cells(); ++c) {
            const double d = diagonal(L.A[size_t(c)], c);
            if (d > 0.0) e[size_t(c)] = k.omega * r[size_t(c)] / d;
        }
    }
    const std::vector<double> Ae = multiply(L.A, e);
    const Matrix& P = h.P[l];
    std::vector<double> rc(size_t(h.levels[l + 1].cells()), 0.0);
    for (size_t i = 0; i < P.size(); ++i)
        for (const auto& [c, p] : P[i]) rc[size_t(c)] += h.scale[l] * p * (r[i] - Ae[i]);
    const std::vector<double> ec = cycle(h, l + 1, rc, k);
    const double alpha = l == 0 ? 1.0 : k.alpha;
    for (size_t i = 0; i < P.size(); ++i)
        for (const auto& [c, p] : P[i]) e[i] += alpha * p * ec[size_t(c)];
    if (l == 0) {
        relax(L, r, e, 1, 2);
        relax(L, r, e, 0, 2);
    } else {
        const std::vector<double> Av = multiply(L.A, e);
        for (int c = 0; c < L.cells(); ++c) {
            const double d = diagonal(L.A[size_t(c)], c);
            if (d > 0.0) e[size_t(c)] += k.omega * (r[size_t(c)] - Av[size_t(c)]) / d;
        }
    }
    return e;
}

}  // namespace

std::vector<double> galerkin_vcycle(const Grid& grid, const std::vector<uint8_t>& type,
                                    const std::vector<double>& extra_diagonal, const std::vector<double>& r,
                                    const GalerkinCycle& k) {
    Hierarchy h;
    Level fine{grid.cell_dims(), type, Matrix(size_t(grid.cells()))};
    for (int c = 0; c < fine.cells(); ++c) {
        if (type[size_t(c)] != FLUID) continue;
        double diag = extra_diagonal.empty() ? 0.0 : extra_diagonal[size_t(c)];
        for (const glm::ivec3& d : kFaces) {
            const glm::ivec3 q = fine.coord(c) + d;
            if (!fine.inside(q) || type[size_t(fine.index(q))] == SOLID) continue;
            diag += 1.0;
            if (type[size_t(fine.index(q))] == FLUID) fine.A[size_t(c)][fine.index(q)] = -1.0;
        }
        fine.A[size_t(c)][c] = diag;
    }
    h.levels.push_back(std::move(fine));
    for (;;) {
        const Level& F = h.levels.back();
        const size_t l = h.levels.size() - 1;
        const bool small = F.cells() <= k.coarse_cells && l != 1;
        if (small || int(h.levels.size()) == k.max_levels) break;
        Level C;
        C.n = (F.n + 1) / 2;
        if (C.n == F.n) break;
        const glm::ivec3 coarsened = glm::ivec3(glm::lessThan(C.n, F.n));
        C.type.assign(size_t(C.cells()), AIR);
        for (int f = 0; f < F.cells(); ++f) {
            const glm::ivec3 q = F.coord(f);
            if (F.type[size_t(f)] == FLUID) C.type[size_t(C.index({q.x >> coarsened.x, q.y >> coarsened.y, q.z >> coarsened.z}))] = FLUID;
        }
        const Matrix P = prolongation(F, C, l == 0);
        const double s = l == 0 ? 4.0 / double(1 << (coarsened.x + coarsened.y + coarsened.z)) : 1.0;
        C.A = galerkin(F.A, P, C.cells(), s);
        h.P.push_back(P);
        h.scale.push_back(s);
        h.levels.push_back(std::move(C));
    }
    return cycle(h, 0, r, k);
}

}  // namespace pf::ref
