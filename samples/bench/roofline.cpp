#include "roofline.h"

#include <glad/gl.h>

#include <algorithm>
#include <chrono>
#include <vector>

#include "gl_util.h"

namespace pfb {
namespace {

// The streaming kernels' common part: vec4s from src to dst, u_per_thread per invocation, a
// dispatch's width apart (coalesced).
#define PFB_STREAM_KERNEL_HEAD \
    "#version 430\n" \
    "layout(local_size_x = 256) in;\n" \
    "layout(std430, binding = 0) readonly buffer Src { vec4 src[]; };\n" \
    "layout(std430, binding = 1) writeonly buffer Dst { vec4 dst[]; };\n" \
    "layout(location = 0) uniform uint u_per_thread;\n" \
    "uint width() { return gl_NumWorkGroups.x * gl_NumWorkGroups.y * 256u; }\n" \
    "uint first() { return gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * 256u; }\n"

// Copy: every vec4 read and written.
const char* kCopy = PFB_STREAM_KERNEL_HEAD R"(
void main() {
    for (uint k = 0u; k < u_per_thread; ++k) dst[first() + k * width()] = src[first() + k * width()];
}
)";

// Read only: nothing is written unless the sum is impossible (so the reads cannot be optimised away).
const char* kRead = PFB_STREAM_KERNEL_HEAD R"(
void main() {
    vec4 sum = vec4(0.0);
    for (uint k = 0u; k < u_per_thread; ++k) sum += src[first() + k * width()];
    if (sum.x == -1.0e30) dst[first()] = sum;
}
)";

// Each invocation adds to 8 addresses from an integer hash of its index and step: no two
// neighbouring invocations share a word, as in the worst case of a particle-to-grid scatter.
const char* kAtomics = R"(#version 430
layout(local_size_x = 256) in;
layout(std430, binding = 0) buffer Counters { uint counters[]; };
layout(location = 0) uniform uint u_mask;
void main() {
    uint h = gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * 256u;
    for (int k = 0; k < 8; ++k) {
        h ^= h >> 16; h *= 0x7feb352du; h ^= h >> 15; h *= 0x846ca68bu; h ^= h >> 16;
        atomicAdd(counters[h & u_mask], 1u);
    }
}
)";

// A link in a chain of dependent dispatches: one workgroup adds to its words and writes the
// indirect record (one workgroup) the next indirect dispatch reads; every other workgroup of a
// wider dispatch does nothing (the cost of launching and draining a grid-sized dispatch).
const char* kChain = R"(#version 430
layout(local_size_x = 256) in;
layout(std430, binding = 0) buffer Words { uint words[]; };
void main() {
    if (gl_WorkGroupID.x != 0u || gl_WorkGroupID.y != 0u) return;
    words[4u + gl_LocalInvocationID.x] += 1u;
    if (gl_LocalInvocationID.x == 0u) words[0] = 1u, words[1] = 1u, words[2] = 1u;
}
)";

constexpr GLuint kGroupsX = 32768;  // dispatches of 2D grids of 256-invocation workgroups

// GPU nanoseconds between GL_TIMESTAMP queries around what `work` records, which ends with a
// storage barrier (timestamp pairs: Mesa's llvmpipe reads ~1 ns for GL_TIME_ELAPSED around a lone
// dispatch).
template <typename Work>
double timestamped_ns(Work&& work) {
    GLuint q[2] = {0, 0};
    glGenQueries(2, q);
    glQueryCounter(q[0], GL_TIMESTAMP);
    work();
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    glQueryCounter(q[1], GL_TIMESTAMP);
    GLuint64 t0 = 0, t1 = 0;
    glGetQueryObjectui64v(q[0], GL_QUERY_RESULT, &t0);
    glGetQueryObjectui64v(q[1], GL_QUERY_RESULT, &t1);
    glDeleteQueries(2, q);
    return t1 > t0 ? double(t1 - t0) : 0.0;
}

// The median of `runs` timings after one untimed (timestamped_ns of `work`), in ns.
template <typename Work>
double median_ns(int runs, Work&& work) {
    std::vector<double> ns;
    for (int r = 0; r <= runs; ++r) {
        const double t = timestamped_ns(work);
        if (r > 0) ns.push_back(t);
    }
    std::sort(ns.begin(), ns.end());
    return ns[ns.size() / 2];
}

// GPU nanoseconds of one (groups_x, groups_y) grid of workgroups of the bound program.
double time_once(GLuint groups_x, GLuint groups_y) {
    return timestamped_ns([&] { glDispatchCompute(groups_x, groups_y, 1); });
}

// Median GPU milliseconds of `runs` timed dispatches of (groups_x, groups_y) after one untimed.
double time_dispatch(GLuint groups_x, GLuint groups_y, int runs) {
    return median_ns(runs, [&] { glDispatchCompute(groups_x, groups_y, 1); }) * 1e-6;
}

// How a chain's dispatches get their size: directly, or from an indirect record that the chain's
// kernel writes (a command barrier before each dispatch), or from one nothing writes.
enum class ChainDispatch { direct, written_record, static_record };

// GPU microseconds per dispatch of `chain` dependent dispatches of (groups, 1) workgroups of the
// bound program, each after a storage barrier (written_record: from the record at the bound
// dispatch indirect buffer's start, after a command barrier too; static_record: from the record
// at `offset` of the bound dispatch indirect buffer); the median of 5 chains after one untimed.
double time_chain(GLuint groups, ChainDispatch how, int chain, GLintptr offset = 0) {
    const bool command = how == ChainDispatch::written_record;
    const double ns = median_ns(5, [&] {
        for (int k = 0; k < chain; ++k) {
            glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | (command ? GL_COMMAND_BARRIER_BIT : 0));
            if (how == ChainDispatch::direct)
                glDispatchCompute(groups, 1, 1);
            else
                glDispatchComputeIndirect(offset);
        }
    });
    return ns * 1e-3 / chain;
}

GLuint make_buffer(GLsizeiptr bytes) {
    GLuint b = 0;
    glGenBuffers(1, &b);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, b);
    glBufferData(GL_SHADER_STORAGE_BUFFER, bytes, nullptr, GL_DYNAMIC_COPY);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    return b;
}

}  // namespace

Ceilings measure_ceilings() {
    Ceilings c;
    const GLuint copy = pfs::link_compute_program(kCopy, "roofline_copy");
    glUseProgram(copy);
    // Without timer queries (Mesa's llvmpipe) nothing can be measured: a one-workgroup probe
    // says so before any large buffer is made.
    GLuint src = make_buffer(256 * 16), dst = make_buffer(256 * 16);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, src);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, dst);
    const bool timed = time_once(1, 1) > 0;
    glDeleteBuffers(1, &src);
    glDeleteBuffers(1, &dst);
    if (timed) {
        // 512 MiB each way (or the GL's largest storage block), far beyond any L2.
        GLint64 max_block = 0;
        glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &max_block);
        const GLsizeiptr copy_bytes = std::min<GLsizeiptr>(GLsizeiptr(512) << 20, GLsizeiptr(max_block));
        src = make_buffer(copy_bytes);
        dst = make_buffer(copy_bytes);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, src);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, dst);
        // Untimed copies for 200 ms first: an idle GPU raises its clocks only under sustained load.
        glUniform1ui(0, 1u);
        const auto warm_until = std::chrono::steady_clock::now() + std::chrono::milliseconds(200);
        while (std::chrono::steady_clock::now() < warm_until) {
            glDispatchCompute(kGroupsX, GLuint(copy_bytes / 16 / 256 / kGroupsX), 1);
            glFinish();
        }
        // The best of 1, 4 and 16 vec4s per invocation, for the copy (bytes read + written) and
        // the read-only stream.
        const GLuint read = pfs::link_compute_program(kRead, "roofline_read");
        for (GLuint program : {copy, read}) {
            glUseProgram(program);
            double& best = program == copy ? c.copy_gbps : c.read_gbps;
            for (GLuint per_thread : {1u, 4u, 16u}) {
                const GLuint groups = GLuint(copy_bytes / 16 / 256 / per_thread);
                const GLuint columns = std::min(groups, kGroupsX), rows = groups / columns;  // whole rows
                glUniform1ui(0, per_thread);
                const double ms = time_dispatch(columns, rows, 5);
                const double moved = (program == copy ? 2.0 : 1.0) * double(rows) * columns * 256 * per_thread * 16;
                // Under 10 us would be a timer's reading, not a copy's (no GPU moves 256 MiB that fast).
                if (ms > 0.01) best = std::max(best, moved / (ms * 1e6));
            }
        }
        glDeleteProgram(read);
        glDeleteBuffers(1, &src);
        glDeleteBuffers(1, &dst);
    }
    const GLuint atomics = pfs::link_compute_program(kAtomics, "roofline_atomics");
    if (timed) {
        // Atomics: 2 rows of invocations x 8 atomics into 16M words (64 MiB).
        const GLuint words = 1u << 24;
        const GLuint counters = make_buffer(GLsizeiptr(words) * 4);
        glUseProgram(atomics);
        glUniform1ui(0, words - 1);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, counters);
        const double atomic_ms = time_dispatch(kGroupsX, 2, 5);
        if (atomic_ms > 0) c.atomics_gops = double(kGroupsX) * 2 * 256 * 8 / (atomic_ms * 1e6);
        glDeleteBuffers(1, &counters);
    }
    const GLuint chain = pfs::link_compute_program(kChain, "roofline_dispatch_chain");
    if (timed) {
        // Dependent dispatches: 1,000 in a chain, timed as one.
        const GLuint words = make_buffer(GLsizeiptr(260) * 4);
        const GLuint record[3] = {1, 1, 1};
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, words);
        glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof record, record);
        glUseProgram(chain);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, words);
        glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, words);
        constexpr int kChainLength = 1000;
        c.dispatch_us = time_chain(1, ChainDispatch::direct, kChainLength);
        c.indirect_dispatch_us = time_chain(1, ChainDispatch::written_record, kChainLength);
        c.wide_dispatch_us = time_chain(4096, ChainDispatch::direct, kChainLength);
        // Records of 1 and 4,096 workgroups in a buffer the kernel does not bind.
        const GLuint statics = make_buffer(32);
        const GLuint sizes[8] = {1, 1, 1, 0, 4096, 1, 1, 0};
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, statics);
        glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof sizes, sizes);
        glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, statics);
        c.static_indirect_dispatch_us = time_chain(1, ChainDispatch::static_record, kChainLength, 0);
        c.wide_static_indirect_dispatch_us = time_chain(4096, ChainDispatch::static_record, kChainLength, 16);
        glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
        glDeleteBuffers(1, &statics);
        glDeleteBuffers(1, &words);
    }
    if (timed) {
        // 1,000 copies of 2 MiB, alternating between two buffer pairs: a barrier before each, or
        // one before each pair.
        constexpr GLuint kVec4s = 131072;
        GLuint pairs[4];
        for (GLuint& b : pairs) b = make_buffer(GLsizeiptr(kVec4s) * 16);
        glUseProgram(copy);
        glUniform1ui(0, 1u);
        for (bool paired : {false, true}) {
            const double ns = median_ns(5, [&] {
                for (int k = 0; k < 1000; ++k) {
                    if (!paired || k % 2 == 0) glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
                    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, pairs[2 * (k % 2)]);
                    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, pairs[2 * (k % 2) + 1]);
                    glDispatchCompute(kVec4s / 256, 1, 1);
                }
            });
            (paired ? c.paired_copy_dispatch_us : c.copy_dispatch_us) = ns * 1e-3 / 1000;
        }
        glDeleteBuffers(4, pairs);
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, 0);
    glUseProgram(0);
    glDeleteProgram(copy);
    glDeleteProgram(atomics);
    glDeleteProgram(chain);
    pfs::check_gl("measure_ceilings");
    return c;
}

Traffic pass_traffic(pf_pass pass, const TrafficInputs& in) {
    const double p = double(in.particles), f = double(in.faces), cells = double(in.cells);
    Traffic t;
    switch (pass) {
        case PF_PASS_P2G:
            // position, velocity (16 bytes each; APIC's affine vectors 48) in; two accumulator
            // words per face and a count per cell out.
            t.bytes = p * (32 + (in.apic ? 48 : 0)) + 8 * f + 4 * cells;
            if (in.p2g == PF_P2G_TILED) {
                t.bytes += p * (8 + 8 + 4 + 4);  // the sort: tile and slot written and read, order written and read
            } else if (in.p2g == PF_P2G_FIXED_POINT) {
                t.atomics = p * 49;  // 2 words x 8 nodes x 3 lattices, and the cell count
            } else {
                t.bytes = 0;  // the float-atomic and gather schemes: no model
            }
            break;
        case PF_PASS_G2P:
            // position and velocity in, velocity out (APIC: affine vectors out); the face
            // velocities (FLIP: and the pre-force ones) in.
            t.bytes = p * (48 + (in.apic ? 48 : 0)) + f * (in.apic ? 4 : 8);
            break;
        case PF_PASS_ADVECT:
            // position and velocity in and out (the velocity for the walls' stop; Runge-Kutta:
            // the face velocities in); the volume correction's move: position in and out, the
            // potential, types and face fractions in.
            t.bytes = p * 64 + (in.rk_advection ? 4 * f : 0);
            if (in.volume_correction) t.bytes += p * 32 + 8 * cells + 4 * f;
            break;
        default: break;
    }
    return t;
}

const char* traffic_model_note() {
    return "modelled traffic: each particle attribute and grid field a pass reads or writes, counted once "
           "(repeated stencil reads and cache hits not counted); roofline = the copy bandwidth measured at start-up";
}

}  // namespace pfb
