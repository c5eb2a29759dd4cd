// One liquid simulation: its GL loader, buffers, programs and the substep pipeline
// (docs/design.md §4). The C API in src/api validates arguments before calling in here.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

#include "api/log.h"
#include "gl/buffer.h"
#include "gl/gl.h"
#include "gl/program.h"
#include "gl/program_binary_cache.h"
#include "gl/readback_ring.h"
#include "gl/state_guard.h"
#include "pf/pf.h"
#include "sim/effects/registry.h"
#include "sim/grid_layout.h"
#include "sim/particle_readback.h"
#include "sim/pass_runner.h"
#include "sim/sim_uniforms.h"
#include "sim/solvers/pressure_solver.h"
#include "sim/step_clock.h"
#include "sim/substep_table.h"
#include "sim/transfer/particle_to_grid.h"
#include "sim/volume_correction.h"

namespace pf {

// Grid buffers tests may read back (raw 32-bit words).
enum class GridBuffer { face_accum, face_vel, face_vel_old, face_valid, face_fraction, cell_count, cell_type, pressure, rhs, status };

class Simulation : private Projector {
public:
    // Loads GL through desc.gl_get_proc_address, checks GL 4.3, allocates and compiles.
    // `desc` must already be validated and have defaults resolved.
    static pf_result create(const pf_sim_desc& desc, std::unique_ptr<Simulation>& out);
    ~Simulation();
    Simulation(const Simulation&) = delete;
    Simulation& operator=(const Simulation&) = delete;

    pf_result add_particles(const float* xyz, const float* vel, uint32_t n);
    pf_result fill_box(const float lo[3], const float hi[3], const float vel[3]);
    pf_result clear_particles();
    // pf_push: velocity impulse in a sphere (arguments validated by the API).
    pf_result push(const float center[3], float radius, const float dv[3]);
    pf_result step(float frame_dt);
    pf_result set_params(const pf_sim_params& params);
    // pf_sim_desc.prepared_features: builds the programs of those effects (nothing else), so that
    // turning them on later compiles nothing.
    pf_result prepare_features(uint32_t features, const char* fn);
    // pf_set_features: initialises the effects turned on for the first time (all or nothing).
    pf_result set_features(uint32_t features, const char* fn);
    uint32_t features() const { return desc_.features; }
    // The effect of class E (its kFeature bit names its slot): the effect's own C API
    // (src/sim/effects/<name>/<name>_api.cpp) edits its objects through it; edits take effect at
    // the next step.
    template <typename E>
    E& effect() {
        constexpr uint32_t slot = effect_slot(E::kFeature);
        static_assert(slot < kEffectCount, "E::kFeature must be one PF_FEATURE_* bit");
        return static_cast<E&>(*effects_[slot]);
    }
    template <typename E>
    const E& effect() const {
        constexpr uint32_t slot = effect_slot(E::kFeature);
        static_assert(slot < kEffectCount, "E::kFeature must be one PF_FEATURE_* bit");
        return static_cast<const E&>(*effects_[slot]);
    }
    // Domain -> world (the renderer's model matrix): the poses of the effects that are on
    // (Effect::domain_to_world; only a domain motion moves it), else the identity.
    glm::mat4 domain_to_world() const;
    pf_result read_particles(uint32_t first, uint32_t count, float* xyz, float* vel) const;
    // pf_request_particles / pf_poll_particles (range checked by the API).
    pf_result request_particles(uint32_t first, uint32_t count, uint32_t* ticket);
    // Snapshots (src/sim/snapshot.cpp): exact size, save (size checked), restore (all checked
    // first; on any error nothing changes).
    size_t snapshot_size() const;
    pf_result save_snapshot(void* buffer, size_t size);
    pf_result restore_snapshot(const void* buffer, size_t size);
    pf_result poll_particles(uint32_t ticket, float* xyz, float* vel);
    const ParticleReadback& particle_requests() const { return *requests_; }
    void gl_buffers(pf_gl_buffers& out) const;
    void stats(pf_stats& out) const;
    // Entries of the runtime per-pass statistics list.
    uint32_t pass_count() const { return uint32_t(runner_->stats().size()); }
    void pass_stats(uint32_t index, pf_pass_stats& out) const;
    void clear_flags();

    const pf_sim_desc& desc() const { return desc_; }
    // m^3 of liquid a particle stands for at rest density.
    double particle_volume() const;
    // Particles per cell of the last substep's P2G, and whether they still describe the particles
    // (a step has run since particles were last added or a snapshot restored).
    const gl::Buffer& cell_count() const { return cell_count_; }
    bool cell_counts_current() const { return cell_counts_current_; }
    // The live particle slots in a spatially coherent order (the P2G scheme's of the last substep,
    // whose first live-count entries are every live slot once: not after particles were added,
    // nor with sinks, which compact the slots after the substeps), or 0.
    GLuint particle_order() const {
        const gl::Buffer* order = p2g_.particle_order(desc_.params);
        const bool covers = cell_counts_current_ && counted_with_ == desc_.params.p2g;
        return order && covers ? order->id() : 0;
    }
    const pf_sim_params& params() const { return desc_.params; }
    const Log& log() const { return log_; }
    const gl::Api& api() const { return gl_; }
    // The engine's program-binary cache (pf_sim_desc.program_cache), which the renderer's programs
    // go through too; inactive without callbacks.
    gl::ProgramBinaryCache* program_binaries() const { return binaries_.get(); }
    // How a gl::StateGuard of this simulation's context saves state (what the context supports).
    const gl::StateGuard::Options& gl_state_options() const { return gl_state_; }
    // Particle slots in use: the live count, or while the GPU keeps the count (emitters or sinks
    // on) an upper bound of it. Never waits.
    uint32_t particle_count() const { return particle_count_; }
    // The exact live count; waits for the GPU while it keeps the count.
    uint32_t live_count() const;
    // True while emitters or sinks are on: the GPU decides the live count (design.md §9.3).
    bool gpu_count() const { return gpu_count_; }
    // The live-count record (PF_COUNT_* words of common/slots.h: two indirect-draw records).
    const gl::Buffer& count_record() const { return count_record_; }
    // Substeps (projection steps) pf_step(frame_dt) would take now, and how far a particle may
    // travel in each (CFL estimate, design.md §5).
    ProjectionCount substeps_for(float frame_dt) const;

    // Test access: one substep of length dt exactly (no CFL logic, no volume correction), and
    // raw grid words.
    pf_result run_substep_for_test(float dt);
    // Test access: the passes the effects that are on run at `stages`, in that order, on the grid
    // as it is (set it with write_grid_for_test), in one step of one substep of length dt; an
    // effect that asks for the projection again gets none.
    pf_result run_effect_stages_for_test(std::initializer_list<EffectStage> stages, float dt);
    // Test access: the volume correction alone, on the cell types and counts as they are (set
    // them with write_grid_for_test); its potential is read with read_volume_potential.
    pf_result run_volume_correction_for_test();
    // Test access: the metrics pass alone on the grid and particles as they are (set them with
    // write_grid_for_test); its words are read with read_grid(GridBuffer::status).
    pf_result run_metrics_for_test();
    std::vector<float> read_volume_potential() const;
    // Test access: the current solver alone on a given system (cell types, right-hand side;
    // `pressure` is the warm start and receives the solution). The status buffer's solver words
    // are reset first and hold this solve's iterations and final residual afterwards.
    pf_result solve_for_test(const std::vector<uint32_t>& cell_type, const std::vector<float>& rhs,
                             std::vector<float>& pressure);
    // Test access: two systems on the same cell types with the volume correction's solver (on,
    // MGPCG), the first with the simulation's parameters and the second with the correction's
    // (VolumeCorrection::solve_params), in one pair solve (`paired`) or as two solves of that
    // solver; each problem's reported iterations into `iterations`.
    pf_result solve_two_for_test(const std::vector<uint32_t>& cell_type, const std::vector<float> (&rhs)[2],
                                 std::vector<float> (&pressure)[2], bool paired, uint32_t (&iterations)[2]);
    // Test access: whether the volume correction's solve may go in the same passes as the
    // projection's (default true; false: the two solve in turn on that solver, as with separation).
    void set_paired_correction_for_test(bool paired) { paired_correction_allowed_ = paired; }
    std::vector<uint32_t> read_grid(GridBuffer which) const;
    void write_grid_for_test(GridBuffer which, const std::vector<uint32_t>& words);
    // The substep table's entries from G2P on (G2P, advection and the effects after it) on the
    // face velocities as they are: tests of the integrators set face_vel with write_grid_for_test.
    pf_result run_g2p_and_advect_for_test(float dt);
    // Test access: the size of the face velocities G2P reads from which it walks the particles in
    // the tiled P2G's order (default kOrderedG2pFaceBytes; 0: always, UINT64_MAX: never).
    pf_result set_ordered_g2p_face_bytes_for_test(uint64_t bytes);
    // Test access: the most mirror orbits a grid may have for its solvers' reduction kernels to run
    // one invocation a cell (default kOneCellReductionOrbits, 0 on a CPU rasteriser; 0: never); the
    // solvers are made again.
    pf_result set_one_cell_reduction_orbits_for_test(uint64_t orbits);
    // Whether this grid's solvers run their reduction kernels one invocation a cell.
    bool one_cell_reductions() const;
    // The most mirror orbits (SolveControl::orbits) of a grid whose solvers' reduction kernels run
    // one invocation a cell (SolverGrid): 65,536, those of 64^3 cells; none on a CPU rasteriser. On
    // the H200 the frame is 3-10% faster up to 96 x 48 x 48 cells; from 128 x 64 x 64, where the
    // orbits fill the GPU, four times more invocations made it slower, and on llvmpipe slower at
    // every size (docs/notes/2026-12-04-reductions-by-grid-size.md). Orbits, not cells: the two
    // mappings' sums match bit for bit while the last workgroup adds at most 512 partials
    // (orbit_main.glsl), and 65,536 orbits make 256 whatever the grid's shape (a slab one cell
    // thick has about one orbit for two cells).
    static constexpr uint64_t kOneCellReductionOrbits = uint64_t(1) << 16;
    // APIC affine vectors of the live particles, 12 floats each (c_x, c_y, c_z as vec4s);
    // empty while APIC was never used.
    std::vector<float> read_affine() const;
    void write_affine_for_test(const std::vector<float>& values);
    const PassRunner& runner() const { return *runner_; }
    // pf_set_gpu_timing / pf_get_gpu_timing (validated).
    void set_gpu_timing(pf_gpu_timing timing);
    pf_gpu_timing gpu_timing() const;
    // pf_set_gpu_budget / pf_get_gpu_budget (validated; 0: none).
    void set_gpu_budget_ms(float ms) { gpu_budget_ms_ = ms; }
    float gpu_budget_ms() const { return gpu_budget_ms_; }
    // The GPU time of the newest measured step, as the budget reads it (the runner's timer queries).
    MeasuredStep measured_step() const;
    // Test access: the budget reads its times from `source` instead (llvmpipe's timers read 0);
    // an empty function restores the timer queries.
    void set_step_time_source_for_test(std::function<MeasuredStep()> source) { step_time_source_ = std::move(source); }
    // Whether the P2G scheme in use sums floats (else fixed point at the range's scale).
    bool p2g_float_sums() const { return p2g_.float_sums(desc_.params); }
    // The substep table's entries, in the order a substep runs them (as the next step would).
    std::vector<std::string> substep_stage_names();

private:
    explicit Simulation(const pf_sim_desc& desc);
    // Snapshot pieces: the host part (descriptor check, params, CPU step state, effects), its
    // GPU part's size, and waiting for the status readbacks in flight.
    struct SnapshotState;
    std::vector<uint8_t> snapshot_host_state() const;
    bool snapshot_has_affine() const;
    size_t snapshot_gpu_bytes(uint32_t particles, bool affine) const;
    void drain_status();
    pf_result init();
    // The solver for params.pressure_solver, made and initialised on first use (kept after), in
    // one of three roles: the projection's; the volume correction's own instance of it (its
    // solve runs alongside the projection's, on its own buffers); the instance that solves both
    // as a pair (MGPCG made for pairs: its buffers are those of two solvers).
    enum class SolverRole { projection, correction, pair };
    pf_result solver_for(const pf_sim_params& params, const char* fn, PressureSolver** out, SolverRole role);
    // The solvers `params` select (the correction's only while it is on; one instance for both
    // where they solve as a pair): every place that changes the parameters (pf_create,
    // pf_set_params, a restore) takes both from here.
    struct SolversInUse {
        PressureSolver* pressure = nullptr;
        PressureSolver* correction = nullptr;
    };
    pf_result solvers_for(const pf_sim_params& params, const char* fn, SolversInUse* out);
    // Whether the volume correction's solve goes in the same passes as the projection's (its
    // solver solves pairs, and the projection asks no separation).
    bool correction_paired() const {
        return paired_correction_allowed_ && solvers_in_use_.correction && solvers_in_use_.correction->solves_pairs() &&
               !desc_.params.separation;
    }
    // The per-particle programs params select after P2G (its scheme's sums, transfer, flip
    // ratio, advection); the P2G scheme must be prepared.
    struct ParticlePrograms {
        gl::ProgramId grid_forces, g2p, advect;
        gl::ProgramId g2p_ordered;  // G2P in the P2G scheme's particle order, if it has one (else g2p)
        gl::ProgramId advect_ordered;  // the advection in that order where it gathers from the grid too (else advect)
    };
    // `features`: the effects on (desc_.features unless they are about to change).
    ParticlePrograms particle_programs(const pf_sim_params& params, uint32_t features) const;
    ParticlePrograms particle_programs(const pf_sim_params& params) const { return particle_programs(params, desc_.features); }
    // Prepares the P2G scheme, builds those programs and, for APIC, allocates the affine buffer
    // (first use only), so that a failure leaves the running simulation untouched.
    pf_result prepare_particle_passes(const pf_sim_params& params, uint32_t features, const char* fn);
    pf_result prepare_particle_passes(const pf_sim_params& params, const char* fn) {
        return prepare_particle_passes(params, desc_.features, fn);
    }
    void zero_affine(uint32_t first, uint32_t count);
    void upload_uniforms(float dt);
    // What the volume correction reads and moves (this substep's buffers).
    VolumeCorrection::Inputs correction_inputs() const;
    // Sets the length of the next particle moves (advection and the passes after it: sim.drift_dt).
    void set_drift(float seconds);
    // Test hooks: one step of length dt that runs `passes` (timed and counted like a step).
    template <typename Passes>
    void run_one_step_for_test(float dt, Passes&& passes);
    // One substep: the substep table (rebuilt first when its shape changed); with
    // `correct_volume` the volume correction's entry runs (after classify, on this substep's
    // counts); with `half_move` its particles move half the substep.
    void run_substep(bool correct_volume, bool half_move = false);
    // PF_ADVECTION_LEAPFROG's first move of a step: half a substep at the velocities the last
    // step left, with the passes that follow advection (design.md §5).
    void run_half_move();
    // Rebuilds the substep table when what decides its entries changed since it was built.
    void update_substep_table();
    // Fills the table: the core stages in order, the entries params ask for, and the entries
    // of every effect that is on after the core stage each of its stages follows.
    void build_substep_table();
    // The parts of the state that decide the table's entries.
    struct SubstepShape {
        uint32_t features = 0;
        pf_free_surface free_surface = PF_FREE_SURFACE_MARKER_CELL;
        bool volume_correction = false;
        bool operator==(const SubstepShape& o) const {
            return features == o.features && free_surface == o.free_surface && volume_correction == o.volume_correction;
        }
    };
    // Every effect that is on, its passes of `stage` (lowest feature bit first).
    void run_effects(EffectStage stage);
    // Start of a step: effects that are on upload what changed.
    void begin_effects_step(float frame_dt);
    // The effects' buffers and sizes for this substep.
    EffectBuffers effect_buffers() const;
    // The projection's first and last passes with `pressure` as the pressure (the substep's, or
    // an effect's potential): the right-hand side from the face velocities, and their update.
    void run_pressure_setup(PassRunner& runner, StatId stat, const gl::Buffer& pressure) const;
    void run_velocity_update(PassRunner& runner, StatId stat, const gl::Buffer& pressure) const;
    // Projector: the projection again, for an effect that changed the velocities after it.
    void project(PassRunner& runner, const gl::Buffer& potential, const gl::Buffer& report, StatId stat,
                 uint32_t recent_iterations, float recent_residual) const override;
    // Runs the once-per-step stage `stage` (emitters, sinks, whitewater), then, while the GPU
    // keeps the live count, hands it to the kernels' uniform block.
    void run_count_stage(EffectStage stage);
    // Writes a host-known live count into the count record.
    void write_count_record(uint32_t live);
    // Copies the GPU's live count into the uniform block (sim.particle_count of the kernels).
    void copy_count_to_uniforms();
    // End of a step: effects that are on start their readbacks.
    void end_effects_step();
    void run_g2p();
    void run_advect();
    const gl::Buffer& grid_buffer(GridBuffer which) const;
    // Takes in every status readback that has arrived (for pf_get_stats and the flags).
    void poll_status() const;
    // Downloads readback slot `s` (blocking if its fence has not passed) and takes it in.
    void read_status_slot(int s) const;
    // Start of step `step`: the inputs that decide how it runs (the CFL speed, the fixed-point
    // P2G range) come from the readback of step `step - kStatusLag` exactly, waited for if the
    // GPU is that far behind. A GPU's timing then never changes the results: NVIDIA, unlike
    // llvmpipe, may not have finished the previous step when the next one starts.
    void take_lagged_status(int64_t step);
    // Accuracy metrics of the step just run (its last substep's grid, its particles), reduced on
    // the GPU into the status buffer: 2 dispatches per step (docs/design.md §4.11).
    void run_metrics();
    // The drifts' reference is taken again (particles were added or cleared).
    void restart_volume_reference();

    // The statistics entries of the core passes (pf_pass order).
    // Logs a warning for a ghost-fluid surface on a stationary solver (valid, but it adds energy).
    void warn_about_free_surface(const pf_sim_params& params, const char* fn) const;

    struct CoreStats {
        StatId clear, grid_forces, classify, pressure_setup, velocity_update, extrapolate, g2p, advect;
        StatId metrics;  // once per step, in the PF_PASS_VELOCITY_UPDATE group
        StatId hydrostatic_start;  // after particles were added, in the PF_PASS_PRESSURE_SETUP group
        StatId free_surface;  // the ghost-fluid words, in the PF_PASS_CLASSIFY group
        StatId wall_release;  // walls that let go of their liquid, in the PF_PASS_PRESSURE_SETUP group
    };

    gl::MemoryTally memory_;  // declared before every buffer: it outlives them (gl_.userptr points here)
    gl::Api gl_{};
    gl::StateGuard::Options gl_state_{};
    pf_sim_desc desc_;
    Log log_;
    gl::Buffer uniforms_;
    std::unique_ptr<gl::ProgramBinaryCache> binaries_;  // before runner_: its programs use it
    std::unique_ptr<PassRunner> runner_;
    CoreStats stat_{};
    std::unique_ptr<PressureSolver> solvers_[PF_PRESSURE_SOLVER_COUNT];
    std::unique_ptr<PressureSolver> correction_solvers_[PF_PRESSURE_SOLVER_COUNT];
    std::unique_ptr<PressureSolver> pair_solvers_[PF_PRESSURE_SOLVER_COUNT];  // SolverRole::pair (the MGPCGs)
    SolversInUse solvers_in_use_;  // the ones params select (the correction's null while it is off)
    bool paired_correction_allowed_ = true;  // set_paired_correction_for_test
    bool correction_pending_ = false;  // this substep's correction waits to be solved with the projection
    VolumeCorrection volume_correction_;
    ParticleToGrid p2g_;  // the schemes, their fixed-point range and the "p2g" statistics entry
    SubstepTable substep_;
    SubstepShape substep_shape_{};
    bool substep_built_ = false;
    // One effect per feature bit (bit i: effects_[i]); made at construction (their host lists
    // exist while off), initialised when first turned on (effects_ready_ bits).
    std::unique_ptr<Effect> effects_[kEffectCount];
    uint32_t effects_ready_ = 0;
    uint32_t requested_features_ = 0;  // desc.features, turned on at the end of init()
    uint32_t step_substeps_ = 1;       // substeps of the step being run (effects weigh their sums by it)
    float travel_cells_ = 1.0f;        // cells a particle may cross in one of its substeps (extrapolation's reach)
    float gpu_budget_ms_ = 0.0f;       // pf_set_gpu_budget (0: none)
    std::function<MeasuredStep()> step_time_source_;  // tests' injected times (empty: the timer queries)
    // Most pressure iterations per solve in the step being run: params.pressure_iterations, or fewer
    // when the budget cut them.
    uint32_t iteration_cap_ = 0;
    // The parameters the step's solves run with (params, their iterations capped by the budget).
    pf_sim_params solve_params() const;

    // particles
    gl::Buffer pos_, vel_;
    std::unique_ptr<ParticleReadback> requests_;  // pf_request_particles
    gl::Buffer affine_;  // APIC: 3 vec4 per particle slot (c_x, c_y, c_z); allocated on first use
    // The live count; while gpu_count_, an upper bound of it (the GPU's count record holds the
    // exact one): raised by what emitters may add, lowered by readbacks of the GPU's count.
    mutable uint32_t particle_count_ = 0;
    gl::Buffer count_record_;     // PF_COUNT_WORDS: kept current in both modes (indirect draws)
    bool gpu_count_ = false;
    uint64_t added_total_ = 0;    // particles added so far (pf_add_particles, emitters' requests)
    mutable uint32_t readback_count_ = 0;  // live count of the newest readback
    mutable uint32_t whitewater_count_ = 0;  // live whitewater particles of the newest readback
    mutable std::array<uint32_t, PF_STATUS_WORDS> status_words_{};  // the newest readback's words (effects read theirs)
    mutable uint32_t viscosity_iterations_ = 0;  // the newest readback's viscosity solve figures
    mutable float viscosity_residual_ = 0.0f;
    // grid
    GridLayout layout_{};  // the grid's cells and faces in storage
    gl::Buffer face_accum_, face_vel_, face_vel_old_, face_valid_[2], face_fraction_;
    gl::Buffer cell_count_, cell_type_, pressure_, rhs_;
    int valid_current_ = 0;     // which valid mask is the latest
    // The next substep starts its solve from the hydrostatic estimate (particles were added to
    // cells whose pressure is 0: creation, pf_add_particles, pf_fill_box; docs/design.md §4.5a).
    bool hydrostatic_start_pending_ = true;
    // The P2G scheme's particle order of this substep, for G2P (set by the p2g stage, cleared
    // by advect, after which positions no longer match it), or null.
    const gl::Buffer* g2p_order_ = nullptr;
    static constexpr uint64_t kOrderedG2pFaceBytes = uint64_t(4) << 20;
    uint64_t ordered_g2p_face_bytes_ = kOrderedG2pFaceBytes;
    uint64_t one_cell_reduction_orbits_ = kOneCellReductionOrbits;
    bool cell_counts_current_ = false;  // cell_count() describes the particles (see its accessor)
    pf_p2g counted_with_ = PF_P2G_COUNT;  // the P2G scheme of the last substep (PF_P2G_COUNT: none, or
                                          // sinks were on, which compact the slots after it)
    SimUniforms uniform_data_{};

    // status (flags, max speed) read back a few steps late, behind fences
    static constexpr int kReadbackSlots = 3;
    gl::Buffer status_;
    gl::ReadbackRing<kReadbackSlots> readback_;  // status_ copies, a few steps late
    mutable uint64_t fence_step_[kReadbackSlots] = {};
    mutable uint64_t status_step_ = 0;     // step of the newest readback
    // What the step logic needs from each readback, kept per slot until the step that takes it
    // (kStatusLag steps later); the slot of step k is k % kReadbackSlots.
    // One step: the previous step's status. pf_step may then wait for the GPU to finish the
    // previous step (it has, unless the caller runs steps back to back with nothing between);
    // a lag of 2 avoided that but its CFL bound (speed two frames old plus two frames of
    // acceleration) asked for ~1.5x the substeps at 0.5 s frames.
    static constexpr uint64_t kStatusLag = 1;
    static_assert(kStatusLag < uint64_t(kReadbackSlots), "a slot is reused only after its step was taken in");
    static_assert(kStatusLag == 1, "substeps_for adds one frame of acceleration to the measured speed");
    struct StepStatus {
        uint32_t valid = 0;     // 0: nothing read into this slot yet, 1: read (a word: snapshots hold it)
        int64_t step = 0;
        float max_speed = 0.0f;
        uint32_t flags = 0;
        float strain = 0.0f;    // PF_STATUS_STRAIN
    };
    mutable StepStatus received_[kReadbackSlots] = {};
    float cfl_speed_ = 0.0f;                  // the max speed the CFL condition starts from...
    float cfl_strain_ = 0.0f;                 // ...the strain its straight-move limit starts from...
    // Step numbers the step logic compares are signed: a restored snapshot places them before
    // the restoring simulation's first step when it has run fewer (src/sim/snapshot.cpp).
    int64_t cfl_step_ = 0;                    // ...measured at the end of this step
    mutable float gpu_max_speed_ = 0.0f;   // its max speed
    mutable uint32_t solver_iterations_ = 0;  // its pressure iterations (most of a substep)
    mutable float solver_residual_ = 0.0f;    // its largest final relative residual
    mutable uint32_t recent_iterations_ = 0;  // its most iterations in a first solve round...
    mutable uint32_t recent_later_iterations_ = 0;  // ...and in one later (active-set) round...
    mutable pf_pressure_solver recent_solver_ = PF_PRESSURE_SOLVER_COUNT;  // ...of this solver
    pf_pressure_solver fence_solver_[kReadbackSlots] = {};  // the solver of each readback's step
    bool fence_capped_[kReadbackSlots] = {};                 // whether the budget cut its solves' iterations
    uint64_t fence_added_[kReadbackSlots] = {};             // and added_total_ then
    mutable uint32_t flags_ = 0;           // sticky PF_FLAG_* bits
    // Adds PF_FLAG_* bits, logging one warning for each bit not already set.
    void raise_flags(uint32_t bits) const;
    // Accuracy metrics of the newest readback (status words PF_STATUS_DIVERGENCE_L2..).
    struct Metrics {
        float divergence_l2 = 0, divergence_max = 0, kinetic_energy = 0, particle_volume = 0;
        float potential_energy = 0;  // from the domain's lowest corner along g, J
        float interior_density = 0;  // mean count / rest over interior FLUID cells (0: none)
        float liquid_volume = 0;     // the particles' rest volume / interior_density, m^3
        float strain = 0;            // PF_STATUS_STRAIN, 1/s^2
        uint32_t fluid_cells = 0;
    };
    mutable Metrics metrics_{};
    mutable Metrics metrics_first_{};      // the reference of the drifts...
    mutable bool metrics_first_set_ = false;
    uint64_t metrics_epoch_step_ = 0;      // ...taken from the first readback of a step >= this one
    mutable double energy_first_ = 0.0;    // mechanical energy reference (PF_FLAG_ENERGY_GAINED)...
    mutable bool energy_first_set_ = false;
    uint64_t energy_epoch_step_ = 0;       // ...from the first readback of a step >= this one
    // Restarts the energy reference: particles added or cleared, a push, new parameters.
    void restart_energy_reference();
    double particle_mass() const;                   // kg
    double lowest_potential_per_particle() const;   // m g . x at the domain's lowest corner, J
    gl::Buffer metrics_partials_;          // three vec4 per workgroup of the metrics pass
    uint64_t flags_cleared_at_step_ = 0;   // pf_clear_flags: ignore flags read back from older steps
    float added_speed_ = 0.0f;             // fastest particle added since...
    int64_t added_at_step_ = 0;            // ...this step (no readback covers it yet)

    // counters
    uint64_t steps_ = 0;
    uint32_t last_substeps_ = 0;
    float last_cpu_ms_ = 0.0f;
    uint32_t fill_calls_ = 0;
};

}  // namespace pf
