// The GPU memory pf_get_stats reports (gpu_memory_bytes, gpu_particle_bytes): the part that
// follows max_particles is exactly proportional to it and is all that changes with it, the rest
// follows the grid, the particle buffers an engine can query are inside it, and a buffer made on
// first use (APIC's affine vectors) counts from then on.
#include <glad/gl.h>

#include "support/sim_fixture.h"

namespace pf::test {
namespace {

class Memory : public GpuTest {
protected:
    pf_stats stats_of(pf_sim* sim) {
        pf_stats st{};
        st.struct_size = sizeof st;
        EXPECT_EQ(pf_get_stats(sim, &st), PF_OK);
        return st;
    }
    pf_stats made(uint32_t nx, uint32_t max_particles) {
        pf_sim_desc d = test_desc(nx, 16, 16, 0.05f);
        d.max_particles = max_particles;
        SimPtr sim = create(d);
        EXPECT_TRUE(sim);
        return sim ? stats_of(sim.get()) : pf_stats{};
    }
};

TEST_F(Memory, ParticlePartFollowsTheCapacityAndTheRestTheGrid) {
    const uint32_t n = 1u << 14;  // above the 16^3 grid's cells: every capacity-sized buffer follows it
    const pf_stats a = made(16, n), b = made(16, 2 * n), c = made(32, n);
    ASSERT_GT(a.gpu_particle_bytes, 0u);
    EXPECT_GT(a.gpu_memory_bytes, a.gpu_particle_bytes);
    EXPECT_EQ(b.gpu_particle_bytes, 2 * a.gpu_particle_bytes);
    EXPECT_EQ(b.gpu_memory_bytes - a.gpu_memory_bytes, b.gpu_particle_bytes - a.gpu_particle_bytes)
        << "a buffer whose size follows max_particles is not counted as a particle buffer";
    EXPECT_EQ(c.gpu_particle_bytes, a.gpu_particle_bytes);
    EXPECT_GT(c.gpu_memory_bytes, a.gpu_memory_bytes);
    // Position and velocity (16 bytes each) and the default P2G's sort (12) at the least.
    EXPECT_GE(a.gpu_particle_bytes / n, 44u);
    RecordProperty("bytes_per_particle_slot", int(a.gpu_particle_bytes / n));
    RecordProperty("bytes_per_cell", int((c.gpu_memory_bytes - a.gpu_memory_bytes) / (16 * 16 * 16)));
}

TEST_F(Memory, EngineVisibleBuffersAreCountedAndFirstUseAddsItsBuffers) {
    pf_sim_desc d = test_desc(16, 16, 16, 0.05f);
    SimPtr sim = create(d);
    ASSERT_TRUE(sim);
    const pf_stats before = stats_of(sim.get());
    pf_gl_buffers buffers{};
    ASSERT_EQ(pf_get_gl_buffers(sim.get(), &buffers), PF_OK);
    GLint64 pos_bytes = 0, vel_bytes = 0;
    glBindBuffer(GL_COPY_READ_BUFFER, buffers.positions);
    glGetBufferParameteri64v(GL_COPY_READ_BUFFER, GL_BUFFER_SIZE, &pos_bytes);
    glBindBuffer(GL_COPY_READ_BUFFER, buffers.velocities);
    glGetBufferParameteri64v(GL_COPY_READ_BUFFER, GL_BUFFER_SIZE, &vel_bytes);
    glBindBuffer(GL_COPY_READ_BUFFER, 0);
    ASSERT_GT(pos_bytes, 0);
    EXPECT_LE(uint64_t(pos_bytes + vel_bytes), before.gpu_particle_bytes);

    pf_sim_params p = pf_default_sim_params();
    ASSERT_EQ(pf_get_params(sim.get(), &p), PF_OK);
    p.transfer = PF_TRANSFER_APIC;
    ASSERT_EQ(pf_set_params(sim.get(), &p), PF_OK);
    const float lo[3] = {0.1f, 0.1f, 0.1f}, hi[3] = {0.4f, 0.4f, 0.4f};
    ASSERT_EQ(pf_fill_box(sim.get(), lo, hi, nullptr), PF_OK);
    ASSERT_EQ(pf_step(sim.get(), 1.0f / 60.0f), PF_OK);
    const pf_stats after = stats_of(sim.get());
    EXPECT_EQ(after.gpu_particle_bytes - before.gpu_particle_bytes, 48ull * d.max_particles)
        << "APIC's affine vectors: 48 bytes per particle slot";
    EXPECT_GE(after.gpu_memory_bytes - before.gpu_memory_bytes, 48ull * d.max_particles);
}

}  // namespace
}  // namespace pf::test
