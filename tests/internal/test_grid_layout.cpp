// GridLayout (src/sim/grid_layout.h) against the CPU reference's grid (tests/reference/
// cpu_reference.h) and against counting: every cell and face sample gets the next address in
// x-fastest order, lattices back to back, and the derived counts (nodes, tiles, walls, columns,
// coarser levels) are what enumerating the cells gives.
#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "reference/cpu_reference.h"
#include "sim/grid_layout.h"

namespace {

const glm::ivec3 kSizes[] = {{2, 2, 2}, {3, 5, 7}, {16, 8, 4}, {7, 2, 9}, {24, 24, 24}};

TEST(GridLayout, AddressesFollowTheReferenceGrid) {
    for (glm::ivec3 d : kSizes) {
        SCOPED_TRACE(testing::Message() << d.x << "x" << d.y << "x" << d.z);
        const pf::GridLayout layout{d};
        pf::ref::Grid ref;
        ref.nx = d.x, ref.ny = d.y, ref.nz = d.z;
        EXPECT_EQ(layout.cells(), uint64_t(ref.cells()));
        EXPECT_EQ(layout.faces(), uint64_t(ref.faces()));
        EXPECT_EQ(layout.accum_words(), 2 * uint64_t(ref.faces()));
        int64_t next = 0;
        for (int k = 0; k < d.z; ++k)
            for (int j = 0; j < d.y; ++j)
                for (int i = 0; i < d.x; ++i) {
                    ASSERT_EQ(layout.cell_index({i, j, k}), next);
                    ASSERT_EQ(layout.cell_index({i, j, k}), int64_t(ref.cell_index(i, j, k)));
                    ++next;
                }
        next = 0;
        for (int a = 0; a < 3; ++a) {
            EXPECT_EQ(layout.face_dims(a), ref.face_dims(a));
            EXPECT_EQ(layout.face_offset(a), uint64_t(ref.face_offset(a)));
            const glm::ivec3 f = layout.face_dims(a);
            for (int k = 0; k < f.z; ++k)
                for (int j = 0; j < f.y; ++j)
                    for (int i = 0; i < f.x; ++i) {
                        ASSERT_EQ(layout.face_index(a, {i, j, k}), next);
                        ASSERT_EQ(layout.face_index(a, {i, j, k}), int64_t(ref.face_index(a, i, j, k)));
                        ++next;
                    }
        }
        EXPECT_EQ(uint64_t(next), layout.faces());
    }
}

TEST(GridLayout, DerivedCountsMatchEnumeratingTheCells) {
    for (glm::ivec3 d : kSizes) {
        SCOPED_TRACE(testing::Message() << d.x << "x" << d.y << "x" << d.z);
        const pf::GridLayout layout{d};
        EXPECT_EQ(layout.nodes(), uint64_t(d.x + 1) * uint64_t(d.y + 1) * uint64_t(d.z + 1));
        EXPECT_EQ(layout.half_cells(), uint64_t(2 * d.x) * uint64_t(2 * d.y) * uint64_t(2 * d.z));
        for (int edge : {2, 4, 8}) {
            std::set<std::tuple<int, int, int>> tiles;
            for (int k = 0; k < d.z; ++k)
                for (int j = 0; j < d.y; ++j)
                    for (int i = 0; i < d.x; ++i) tiles.insert({i / edge, j / edge, k / edge});
            EXPECT_EQ(layout.tiles(edge), uint64_t(tiles.size())) << "edge " << edge;
        }
        uint64_t walls = 0;
        for (int a = 0; a < 3; ++a) {
            uint64_t columns = 0;
            for (int k = 0; k < d.z; ++k)
                for (int j = 0; j < d.y; ++j)
                    for (int i = 0; i < d.x; ++i) {
                        const glm::ivec3 c(i, j, k);
                        columns += c[a] == 0;  // one cell of each column lies on the axis' low wall
                    }
            EXPECT_EQ(layout.columns(a), columns) << "axis " << a;
            walls += columns;
        }
        EXPECT_EQ(layout.wall_cells(), walls);
        // Each coarser cell covers the 2 x 2 x 2 block of finer cells it starts (fewer at an odd edge).
        std::set<std::tuple<int, int, int>> parents;
        for (int k = 0; k < d.z; ++k)
            for (int j = 0; j < d.y; ++j)
                for (int i = 0; i < d.x; ++i) parents.insert({i / 2, j / 2, k / 2});
        EXPECT_EQ(layout.coarsened().cells(), uint64_t(parents.size()));
    }
}

TEST(GridLayout, OfTakesTheDescriptorsGridSize) {
    const uint32_t size[3] = {5, 6, 7};
    EXPECT_EQ(pf::GridLayout::of(size).dims, glm::ivec3(5, 6, 7));
}

}  // namespace
