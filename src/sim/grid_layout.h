// Where a grid's cells and face samples live in storage, on the CPU side: the sizes of every
// per-cell and per-face buffer, the dispatch counts of cell and face passes, and the flat
// addresses that shaders/common/grid_layout.glsl and common/sim.glsl compute on the GPU. Every
// lattice is a dense box, x fastest (docs/design.md §2); a sparse layout would change this one
// place and its shader counterpart.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

namespace pf {

struct GridLayout {
    glm::ivec3 dims{0};  // cells per axis

    static GridLayout of(const uint32_t grid_size[3]) {
        return GridLayout{glm::ivec3(int(grid_size[0]), int(grid_size[1]), int(grid_size[2]))};
    }

    uint64_t cells() const { return volume(dims); }
    // Samples per axis of face lattice `axis` (0 = u, 1 = v, 2 = w), their count, and where the
    // lattice starts in the face buffers (u, v, w back to back).
    glm::ivec3 face_dims(int axis) const {
        glm::ivec3 d = dims;
        d[axis] += 1;
        return d;
    }
    uint64_t face_count(int axis) const { return volume(face_dims(axis)); }
    uint64_t faces() const { return face_count(0) + face_count(1) + face_count(2); }
    uint64_t face_offset(int axis) const {
        return axis == 0 ? 0 : axis == 1 ? face_count(0) : face_count(0) + face_count(1);
    }
    // Words of the P2G accumulator: momentum and weight per face sample.
    uint64_t accum_words() const { return 2 * faces(); }
    // Cell corners (viscosity's stress nodes) and half cells (the sorted gather's buckets).
    uint64_t nodes() const { return volume(dims + 1); }
    uint64_t half_cells() const { return 8 * cells(); }
    // Tiles of `edge` cells a side covering the grid (the last ones partly outside it).
    glm::ivec3 tile_dims(int edge) const { return (dims + edge - 1) / edge; }
    uint64_t tiles(int edge) const { return volume(tile_dims(edge)); }
    // One layer of cells against a wall of each axis, all three together (sim/wall_release.comp's
    // invocations), and the columns of cells along `axis` (sim/hydrostatic_start.comp's).
    uint64_t wall_cells() const {
        return uint64_t(dims.y) * uint64_t(dims.z) + uint64_t(dims.x) * uint64_t(dims.z) + uint64_t(dims.x) * uint64_t(dims.y);
    }
    uint64_t columns(int axis) const { return cells() / uint64_t(dims[axis]); }
    // The next multigrid level: each axis halved, rounding up.
    GridLayout coarsened() const { return GridLayout{(dims + 1) / 2}; }

    int64_t cell_index(glm::ivec3 c) const { return index(dims, c); }
    int64_t face_index(int axis, glm::ivec3 f) const { return int64_t(face_offset(axis)) + index(face_dims(axis), f); }

    static uint64_t volume(glm::ivec3 d) { return uint64_t(d.x) * uint64_t(d.y) * uint64_t(d.z); }
    static int64_t index(glm::ivec3 d, glm::ivec3 c) { return c.x + int64_t(d.x) * (c.y + int64_t(d.y) * c.z); }
};

}  // namespace pf
