// The interface every effect implements (docs/design.md §9). An effect is one PF_FEATURE_* bit
// and one module: src/sim/effects/<name>/ (this interface, its object list and parameters),
// shaders/effects/<name>/ (its kernels, lines in shaders/permutations.inc) and its tests. It
// owns its programs, buffers and statistics entries, and makes them only when its feature is
// first turned on (init), so an effect that is off costs nothing: no program is built, no pass
// dispatched, no statistics entry listed. Adding an effect: a class here, a feature bit in
// pf.h, one case in make_effect (registry.cpp), its passes at the stages it needs, its host
// state in snapshots (save_state / restore_state), and its C entry points, defaults and
// validation in <name>_api.cpp. What the simulation needs from it (its part of the CFL bound,
// parameter changes, a restart when turned on, the domain's pose) goes through this interface;
// the simulation reaches an effect's own object API through Simulation::effect<E>(). Effects that add or remove particles
// (emitters, sinks) make the simulation keep its live count on the GPU (docs/design.md §9.3).
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "api/log.h"
#include "gl/buffer.h"
#include "gl/gl.h"
#include "pf/pf.h"
#include "sim/grid_layout.h"
#include "sim/pass_runner.h"
#include "sim/snapshot_io.h"
#include "sim/solvers/pressure_solver.h"

namespace pf {

// The pressure projection, offered to effects that change the velocities after it.
class Projector {
public:
    virtual ~Projector() = default;
    // Makes the face velocities divergence-free again: the pressure setup, a solve (without
    // separation) and the velocity update, with `potential` (a value per cell, the effect's own;
    // its values are the solve's starting guess) as the pressure and `report` (PF_STATUS_WORDS) as the solver's
    // status buffer, so the substep's pressure and the step's solver figures stay the first
    // projection's. `recent_iterations` and `recent_residual` are what such solves needed and
    // reached lately, read back from `report` (kUnknownIterations and -1 until known): the
    // solver issues that need and a margin, not its cap. Counted and timed as entry `stat`.
    virtual void project(PassRunner& runner, const gl::Buffer& potential, const gl::Buffer& report, StatId stat,
                         uint32_t recent_iterations, float recent_residual) const = 0;
};

// The simulation's buffers an effect's passes may bind, and their sizes in this substep.
struct EffectBuffers {
    const gl::Buffer& pos;         // particle positions (vec4)
    const gl::Buffer& vel;         // particle velocities (vec4)
    const gl::Buffer& face_accum;  // P2G sums (momentum, weight) per face
    bool p2g_float = false;        // face_accum holds floats (else fixed point at sim.inv_*_scale)
    const gl::Buffer& face_vel;    // face velocities
    const gl::Buffer& face_vel_old;  // face velocities at the substep's start (after P2G)
    const gl::Buffer& face_fraction;  // the free surface's theta per face (common/free_surface.glsl)
    const gl::Buffer& cell_type;   // AIR / FLUID / SOLID per cell
    const gl::Buffer& count_record;  // the live-count record (PF_COUNT_* in common/slots.h)
    const gl::Buffer& status;      // the step's status words (flags)
    const gl::Buffer* affine;      // APIC affine vectors while params.transfer is APIC, else nullptr
    const gl::Buffer& pressure;    // the substep's solved pressure (Pa) per cell
    uint32_t particles = 0;        // particle slots passes cover (an upper bound of the live count
                                   // while the GPU keeps it: kernels compare with sim.particle_count)
    GridLayout layout{};           // the grid's cells and faces (sim/grid_layout.h)
    uint32_t substeps = 1;         // substeps of the current step
    const Projector* projector = nullptr;  // the simulation's pressure projection
};

// What an effect learns at the start of each pf_step.
struct FrameInfo {
    float frame_dt = 0.0f;          // s
    uint64_t step = 0;              // pf_step number (1 for the first)
    double particle_volume = 0.0;   // m^3 of liquid one particle stands for at rest density
    const uint32_t* status = nullptr;  // the newest status words read back (PF_STATUS_WORDS of them,
                                       // shaders/common/slots.h), measured at step status_step
    uint64_t status_step = 0;       // 0: none read back yet
};

// The points of a step (docs/design.md §4) where effects add passes, in step order: the
// substep stages repeat every substep, the others run once per step.
enum class EffectStage : uint8_t {
    before_substeps,    // once per step, before the first substep (emitters add particles)
    before_first_move,  // once per step, PF_ADVECTION_LEAPFROG only: cells are all AIR before the
                        // half move that precedes the first projection (obstacles mark SOLID)
    after_grid_forces,  // face velocities hold u_old + gravity (force fields)
    after_classify,     // cells are FLUID / AIR (obstacles mark SOLID and set their faces)
    after_velocity_update,  // the pressure is solved and applied (obstacles sum their forces)
    after_advect,       // particles have moved (obstacles push them out)
    after_substeps,     // once per step, after the last substep (sinks remove particles)
};

// What an effect adds to a step's CFL estimate (Simulation::substeps_for).
struct CflBound {
    float acceleration = 0.0f;  // m/s^2 it may add to the liquid's (summed with gravity's)
    float speed = 0.0f;         // m/s the liquid may reach through it whatever was measured (a
                                // wind's drag, an obstacle's surface pushing it)
    float max_dt = 0.0f;        // s: the longest substep it stays stable at (0: no limit)
};

// The bit of `stage` in Effect::stages().
constexpr uint32_t stage_bit(EffectStage stage) { return 1u << uint32_t(stage); }

class Effect {
public:
    virtual ~Effect() = default;
    // Its PF_FEATURE_* bit.
    virtual uint32_t feature() const = 0;
    // Its short name: entries of the substep table are "<name>/<stage>".
    virtual const char* name() const = 0;
    // The stages it runs passes in (stage_bit of each): the substep stages get table entries.
    virtual uint32_t stages() const = 0;
    // Builds its programs, allocates its buffers and registers its statistics entries; called
    // the first time its feature is turned on. Errors are logged (prefixed with fn) and
    // returned; the effect then stays off and may be tried again.
    virtual pf_result init(const gl::Api& gl, PassRunner& runner, const Log& log, const char* fn) = 0;
    // The programs init builds (all of them: pf_sim_desc.prepared_features builds these alone
    // at pf_create, and init then finds them built).
    virtual std::vector<gl::ProgramId> programs() const = 0;
    // Builds (or finds built) every program of programs(); the first failure is logged (prefixed
    // with fn) and returned. init calls it, and so does pf_create for prepared features.
    pf_result prepare_programs(PassRunner& runner, const Log& log, const char* fn) const {
        for (gl::ProgramId id : programs()) {
            if (std::string error = runner.prepare(id); !error.empty())
                return log.error(PF_ERROR_SHADER_COMPILE, std::string(fn) + ": " + error);
        }
        return PF_OK;
    }
    // Start of a step (GL state guarded): upload what changed on the host since the last step.
    virtual void begin_step() = 0;
    // Records its passes of one substep at `stage`, one of its stages().
    virtual void run(EffectStage stage, PassRunner& runner, const EffectBuffers& buffers) = 0;
    // Start of a step, before begin_step: the frame's length (emitters turn rates into counts).
    virtual void begin_frame(const FrameInfo&) {}
    // End of a step (after its last pass, GL state guarded): start the readbacks of what the
    // step measured (copies behind fences, never waited for).
    virtual void end_step(PassRunner& runner, uint64_t step) {
        (void)runner;
        (void)step;
    }
    // True while it does work on the liquid (adds energy): PF_FLAG_ENERGY_GAINED then takes its
    // reference after the last such step instead of before it.
    virtual bool does_work() const { return false; }
    // Particles this step's passes may append after the live ones (the host raises its upper
    // bound of the live count by it); only effects that keep the count on the GPU add any.
    virtual uint32_t particles_added() const { return 0; }
    // True while its passes may change which particles exist (the volume reference restarts).
    virtual bool changes_particles() const { return false; }
    // True if its passes may add particles in a step (known before the step's begin_frame): a
    // simulation with no particles then still takes its CFL substeps instead of one.
    virtual bool adds_particles() const { return false; }
    // Fastest speed (m/s) it gives particles this step: the CFL estimate includes it.
    virtual float added_speed() const { return 0.0f; }
    // Its part of the CFL estimate of a step whose liquid moves at most `speed` m/s (measured,
    // and what effects add).
    virtual CflBound cfl_bound(float speed) const {
        (void)speed;
        return {};
    }
    // pf_set_params changed the simulation's parameters (on or off, every effect hears it).
    virtual void params_changed(const pf_sim_params& params) { (void)params; }
    // Its feature was just turned on: what it measured in an earlier period is stale.
    virtual void turned_on() {}
    // Domain -> world transform of the liquid's frame (the renderer's model matrix) while it is
    // on; effects that do not move the domain keep the identity.
    virtual glm::mat4 domain_to_world() const { return glm::mat4(1.0f); }
    // Snapshots (pf_save_snapshot): appends the host state that determines later steps (its
    // object list, ids included), whether or not the effect is on. Its GPU state is uploaded
    // from that state, so it is not saved.
    virtual void save_state(ByteWriter& out) const = 0;
    // Reads what save_state wrote and validates it (errors logged, prefixed with fn); replaces
    // the host state and marks it for upload only if all of it is valid, else changes nothing.
    virtual pf_result restore_state(ByteReader& in, const Log& log, const char* fn) = 0;
};

}  // namespace pf
