#include "sim/simulation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "common/slots.h"
#include "gl/allocation_check.h"
#include "gl/debug.h"
#include "gl/entry_points.h"
#include "gl/implementation.h"
#include "gl/state_guard.h"
#include "sim/particle_fill.h"
#include "sim/solvers/common/solve_control.h"

namespace pf {

static_assert(PF_GPU_FLAG_P2G_OVERFLOW == PF_FLAG_P2G_OVERFLOW, "flag bits shared with GLSL");
static_assert(PF_GPU_FLAG_NONFINITE == PF_FLAG_NONFINITE, "flag bits shared with GLSL");
static_assert(PF_GPU_FLAG_SPEED_CLAMPED == PF_FLAG_SPEED_CLAMPED, "flag bits shared with GLSL");
static_assert(PF_GPU_FLAG_EMITTERS_FULL == PF_FLAG_EMITTERS_FULL, "flag bits shared with GLSL");

namespace {
using gl::ProgramId;

struct GlFunctionLoader {
    pf_gl_get_proc_address_fn fn;
};

GLADapiproc load_gl(void* user, const char* name) {
    return reinterpret_cast<GLADapiproc>(static_cast<GlFunctionLoader*>(user)->fn(name));
}

using gl::hex;
}  // namespace

Simulation::Simulation(const pf_sim_desc& desc) : desc_(desc), log_(desc.logger) {
    for (uint32_t i = 0; i < kEffectCount; ++i) effects_[i] = make_effect(1u << i, desc);
    requested_features_ = desc.features;
    desc_.features = 0;  // init() turns them on
}

Simulation::~Simulation() = default;  // the readback ring deletes its fences

pf_result Simulation::create(const pf_sim_desc& desc, std::unique_ptr<Simulation>& out) {
    std::unique_ptr<Simulation> sim(new Simulation(desc));
    const pf_result r = sim->init();
    if (r == PF_OK) out = std::move(sim);
    return r;
}

pf_result Simulation::init() {
    GlFunctionLoader loader{desc_.gl_get_proc_address};
    const int version = gladLoadGLContextUserPtr(&gl_, load_gl, &loader);
    if (version == 0) {
        gl_ = gl::Api{};
        return log_.error(PF_ERROR_GL_UNSUPPORTED,
                          "pf_create: could not load OpenGL through gl_get_proc_address (is a GL context current?)");
    }
    const int major = GLAD_VERSION_MAJOR(version), minor = GLAD_VERSION_MINOR(version);
    if (major < 4 || (major == 4 && minor < 3)) {
        gl_ = gl::Api{};
        return log_.error(PF_ERROR_GL_UNSUPPORTED, "pf_create: OpenGL 4.3 core is required, the current context is " +
                                                       std::to_string(major) + "." + std::to_string(minor));
    }
    if (const char* missing = gl::first_missing_entry_point(gl_)) {
        gl_ = gl::Api{};
        return log_.error(PF_ERROR_GL_UNSUPPORTED,
                          std::string("pf_create: the GL loader returned no address for ") + missing);
    }
    gl_.userptr = &memory_;  // every buffer made with this context counts itself (gl/memory_tally.h)
    // GL 4.4 added GL_QUERY_BUFFER, which redirects query results: the state guard parks it.
    gl_state_.query_buffer = major > 4 || minor >= 4;
    // On a CPU rasteriser the solvers' reductions gain nothing from an invocation a cell.
    if (gl::runs_on_the_cpu(gl_)) one_cell_reduction_orbits_ = 0;
    // A GL error the engine left pending would be mistaken for ours below.
    if (GLenum pending = gl_.GetError(); pending != GL_NO_ERROR) {
        log_.warning("pf_create: a GL error (" + hex(pending) + ") was pending before the call; it was consumed");
    }

    layout_ = GridLayout::of(desc_.grid_size);

    GLint max_blocks = 0;
    gl_.GetIntegerv(GL_MAX_COMPUTE_SHADER_STORAGE_BLOCKS, &max_blocks);
    if (max_blocks < PF_SLOT_COUNT) {
        return log_.error(PF_ERROR_GL_UNSUPPORTED, "pf_create: the GL offers " + std::to_string(max_blocks) +
                                                       " compute storage blocks, 8 are needed");
    }
    const uint64_t largest = std::max<uint64_t>(uint64_t(desc_.max_particles) * 16u, layout_.accum_words() * 4u);
    if (pf_result r = gl::check_storage_block(gl_, log_, largest, "pf_create: the simulation needs",
                                              "(16 per particle, 8 per face)", "lower max_particles or the grid size");
        r != PF_OK)
        return r;

    gl::StateGuard guard(gl_, gl_state_);
    const size_t np = desc_.max_particles;
    pos_ = gl::Buffer(gl_, np * 16, GL_DYNAMIC_DRAW, "particle_pos", gl::Sizing::particles);
    vel_ = gl::Buffer(gl_, np * 16, GL_DYNAMIC_DRAW, "particle_vel", gl::Sizing::particles);
    face_accum_ = gl::Buffer(gl_, size_t(layout_.accum_words()) * 4, GL_DYNAMIC_COPY, "face_accum");
    face_vel_ = gl::Buffer(gl_, size_t(layout_.faces()) * 4, GL_DYNAMIC_COPY, "face_vel");
    face_vel_old_ = gl::Buffer(gl_, size_t(layout_.faces()) * 4, GL_DYNAMIC_COPY, "face_vel_old");
    face_fraction_ = gl::Buffer(gl_, size_t(layout_.faces()) * 4, GL_DYNAMIC_COPY, "face_fraction");
    for (auto& b : face_valid_) b = gl::Buffer(gl_, size_t(layout_.faces()) * 4, GL_DYNAMIC_COPY, "face_valid");
    cell_count_ = gl::Buffer(gl_, size_t(layout_.cells()) * 4, GL_DYNAMIC_COPY, "cell_count");
    cell_type_ = gl::Buffer(gl_, size_t(layout_.cells()) * 4, GL_DYNAMIC_COPY, "cell_type");
    pressure_ = gl::Buffer(gl_, size_t(layout_.cells()) * 4, GL_DYNAMIC_COPY, "pressure");
    rhs_ = gl::Buffer(gl_, size_t(layout_.cells()) * 4, GL_DYNAMIC_COPY, "rhs");
    uniforms_ = gl::Buffer(gl_, sizeof(SimUniforms), GL_DYNAMIC_DRAW, "sim_uniforms");
    count_record_ = gl::Buffer(gl_, PF_COUNT_WORDS * 4, GL_DYNAMIC_COPY, "count_record");
    status_ = gl::Buffer(gl_, PF_STATUS_WORDS * 4, GL_DYNAMIC_COPY, "status");
    readback_.init(gl_, PF_STATUS_WORDS * 4, "status_readback");
    binaries_ = std::make_unique<gl::ProgramBinaryCache>(gl_, desc_.program_cache, log_);
    runner_ = std::make_unique<PassRunner>(gl_, log_, uniforms_, PF_UBO_SIM, binaries_.get());
    requests_ = std::make_unique<ParticleReadback>(gl_);
    const uint64_t metric_items = std::max<uint64_t>(layout_.cells(), desc_.max_particles);
    metrics_partials_ = gl::Buffer(gl_, size_t(runner_->workgroups(metric_items).total()) * 48, GL_DYNAMIC_COPY,
                                   "metrics_partials",
                                   desc_.max_particles >= layout_.cells() ? gl::Sizing::particles : gl::Sizing::other);
    if (pf_result r = gl::check_allocated(gl_, log_, "pf_create: allocating " + std::to_string(memory_.bytes >> 20) +
                                                         " MiB of GPU buffers");
        r != PF_OK)
        return r;

    PassRunner& r = *runner_;
    const StatId clear = r.add_stat("clear", PF_PASS_CLEAR);
    p2g_.init(r, P2gGrid{layout_, desc_.max_particles});  // "p2g", after "clear"
    stat_ = CoreStats{clear,
                      r.add_stat("grid_forces", PF_PASS_GRID_FORCES),
                      r.add_stat("classify", PF_PASS_CLASSIFY),
                      r.add_stat("pressure_setup", PF_PASS_PRESSURE_SETUP),
                      r.add_stat("velocity_update", PF_PASS_VELOCITY_UPDATE),
                      r.add_stat("extrapolate", PF_PASS_EXTRAPOLATE),
                      r.add_stat("g2p", PF_PASS_G2P),
                      r.add_stat("advect", PF_PASS_ADVECT),
                      r.add_stat("metrics", PF_PASS_VELOCITY_UPDATE),
                      r.add_stat("hydrostatic_start", PF_PASS_PRESSURE_SETUP),
                      r.add_stat("free_surface", PF_PASS_CLASSIFY),
                      r.add_stat("wall_release", PF_PASS_PRESSURE_SETUP)};
    const ProgramId needed[] = {ProgramId::fill, ProgramId::classify, ProgramId::free_surface,
                                ProgramId::wall_release, ProgramId::pressure_setup, ProgramId::velocity_update, ProgramId::extrapolate,
                                ProgramId::metrics, ProgramId::metrics_finish, ProgramId::hydrostatic_start};
    for (ProgramId id : needed) {
        if (std::string error = r.prepare(id); !error.empty())
            return log_.error(PF_ERROR_SHADER_COMPILE, "pf_create: " + error);
    }
    if (pf_result res = prepare_particle_passes(desc_.params, requested_features_, "pf_create"); res != PF_OK) return res;
    if (pf_result res = solvers_for(desc_.params, "pf_create", &solvers_in_use_); res != PF_OK) return res;
    warn_about_free_surface(desc_.params, "pf_create");
    if (std::string error = volume_correction_.init(gl_, r, uint32_t(layout_.cells())); !error.empty())
        return log_.error(PF_ERROR_SHADER_COMPILE, "pf_create: " + error);
    if (pf_result res = set_features(requested_features_, "pf_create"); res != PF_OK) return res;
    if (pf_result res = prepare_features(desc_.prepared_features, "pf_create"); res != PF_OK) return res;
    if (binaries_->active()) {
        const gl::ProgramBinaryCache::Counts& c = binaries_->counts();
        log_.info("pf_create: program cache: " + std::to_string(c.loaded) + " programs loaded, " +
                  std::to_string(c.compiled) + " compiled (" + std::to_string(c.rejected) + " blobs rejected), " +
                  std::to_string(c.stored) + " stored");
    }
    // Pressure starts at zero (warm start of the first solve); everything else is written
    // before it is read.
    runner_->fill(pressure_, uint32_t(layout_.cells()), 0u, stat_.clear);
    runner_->fill(face_fraction_, uint32_t(layout_.faces()), 0x3f800000u, stat_.clear);  // 1.0f: the marker-cell surface
    runner_->fill(status_, PF_STATUS_WORDS, 0u, stat_.clear);
    const uint32_t record[PF_COUNT_WORDS] = {0, 1, 0, 0, 4, 0, 0, 0};
    count_record_.upload(0, sizeof(record), record);
    return PF_OK;
}

glm::mat4 Simulation::domain_to_world() const {
    glm::mat4 pose(1.0f);
    for (uint32_t i = 0; i < kEffectCount; ++i) {
        if (desc_.features & (1u << i)) pose = effects_[i]->domain_to_world() * pose;
    }
    return pose;
}

void Simulation::write_count_record(uint32_t live) {
    count_record_.upload(PF_COUNT_LIVE * 4, 4, &live);
    count_record_.upload(PF_COUNT_INSTANCES * 4, 4, &live);
}

void Simulation::copy_count_to_uniforms() {
    runner_->copy(count_record_, PF_COUNT_LIVE * 4, uniforms_, offsetof(SimUniforms, particle_count), 4);
}

uint32_t Simulation::live_count() const {
    if (!gpu_count_) return particle_count_;
    gl::StateGuard guard(gl_, gl_state_);
    uint32_t live = 0;
    count_record_.download(PF_COUNT_LIVE * 4, 4, &live);
    particle_count_ = live;  // everything queued has run: the bound is exact again
    return live;
}

pf_result Simulation::solvers_for(const pf_sim_params& params, const char* fn, SolversInUse* out) {
    SolversInUse s;
    const bool correction = params.volume_correction > 0.0f;
    const bool multigrid =
        params.pressure_solver == PF_PRESSURE_SOLVER_MGPCG || params.pressure_solver == PF_PRESSURE_SOLVER_MGPCG_GALERKIN;
    if (multigrid && (correction || pair_solvers_[params.pressure_solver])) {
        // One instance made for pairs solves both: the correction's problem and the projection's
        // as a pair (without separation; with it, the two in turn), and the projections the
        // correction does not go with (later substeps, effects). Its buffers are two solvers';
        // once made it also serves while the correction is off, so switching allocates nothing.
        if (pf_result r = solver_for(params, fn, &s.pressure, SolverRole::pair); r != PF_OK) return r;
        if (correction) s.correction = s.pressure;
        *out = s;
        return PF_OK;
    }
    if (pf_result r = solver_for(params, fn, &s.pressure, SolverRole::projection); r != PF_OK) return r;
    if (correction) {
        if (pf_result r = solver_for(params, fn, &s.correction, SolverRole::correction); r != PF_OK) return r;
    }
    *out = s;
    return PF_OK;
}

pf_result Simulation::solver_for(const pf_sim_params& params, const char* fn, PressureSolver** out, SolverRole role) {
    std::unique_ptr<PressureSolver>& slot = role == SolverRole::pair         ? pair_solvers_[params.pressure_solver]
                                            : role == SolverRole::correction ? correction_solvers_[params.pressure_solver]
                                                                             : solvers_[params.pressure_solver];
    if (!slot) {
        std::unique_ptr<PressureSolver> made = make_pressure_solver(params.pressure_solver, role == SolverRole::pair);
        if (!made) return log_.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": unknown pressure solver");
        const SolverGrid grid{layout_, one_cell_reductions()};
        if (pf_result r = made->init(gl_, *runner_, grid, log_, fn); r != PF_OK) return r;
        if (pf_result r = gl::check_allocated(gl_, log_, std::string(fn) + ": allocating the pressure solver"); r != PF_OK)
            return r;
        slot = std::move(made);
    }
    *out = slot.get();
    return PF_OK;
}

namespace {
// The permutation of a G2P or trace kernel whose stencil stops at obstacles; Euler's move samples
// no grid and is its own.
ProgramId with_solid_walls(ProgramId id) {
    switch (id) {
        case ProgramId::g2p_flip: return ProgramId::g2p_flip_walls;
        case ProgramId::g2p_pic: return ProgramId::g2p_pic_walls;
        case ProgramId::g2p_apic: return ProgramId::g2p_apic_walls;
        case ProgramId::g2p_flip_ordered: return ProgramId::g2p_flip_ordered_walls;
        case ProgramId::g2p_pic_ordered: return ProgramId::g2p_pic_ordered_walls;
        case ProgramId::advect_rk2: return ProgramId::advect_rk2_walls;
        case ProgramId::advect_rk3: return ProgramId::advect_rk3_walls;
        case ProgramId::advect_rk2_offset: return ProgramId::advect_rk2_offset_walls;
        case ProgramId::advect_rk2_offset_ordered: return ProgramId::advect_rk2_offset_ordered_walls;
        default: return id;
    }
}
}  // namespace

Simulation::ParticlePrograms Simulation::particle_programs(const pf_sim_params& params, uint32_t features) const {
    ParticlePrograms p{};
    const bool apic = params.transfer == PF_TRANSFER_APIC;
    p.grid_forces = p2g_.float_sums(params) ? ProgramId::grid_forces_float : ProgramId::grid_forces;
    // Pure PIC skips the FLIP delta (and its u_old reads) in a permutation of its own.
    p.g2p = apic ? ProgramId::g2p_apic : params.flip_ratio > 0.0f ? ProgramId::g2p_flip : ProgramId::g2p_pic;
    // A scheme that groups particles by tile lets G2P read the grid in that order, which pays
    // from a few MiB of face velocities once the particles' memory order has lost its spatial
    // order (docs/notes/2026-12-04-ordered-particle-passes.md: on the H200 after 150
    // frames, dam_break_1m 18-31% faster, 1 MiB grids 0-3% slower). APIC's G2P keeps slot order:
    // its 64 bytes a particle of writes scatter in tile order (dam_break_10m 57% slower, "Tried
    // and not kept: APIC's G2P in the tiled P2G's particle order").
    const bool flip = params.flip_ratio > 0.0f;
    const uint64_t face_bytes = layout_.faces() * sizeof(float) * (flip ? 2u : 1u);
    const bool ordered = !apic && face_bytes >= ordered_g2p_face_bytes_ && p2g_.has_particle_order(params);
    p.g2p_ordered = !ordered ? p.g2p : flip ? ProgramId::g2p_flip_ordered : ProgramId::g2p_pic_ordered;
    p.advect = params.advection == PF_ADVECTION_RK2          ? ProgramId::advect_rk2
               : params.advection == PF_ADVECTION_RK3        ? ProgramId::advect_rk3
               : params.advection == PF_ADVECTION_RK2_OFFSET ? ProgramId::advect_rk2_offset
                                                             : ProgramId::advect;
    // RK2_OFFSET's trace gathers the grid at two points a particle at least (measured on the
    // H200: unordered, and with a third, it made dam_break_10m's frame 1.56 times Euler's); the
    // other schemes keep their memory order.
    p.advect_ordered =
        ordered && params.advection == PF_ADVECTION_RK2_OFFSET ? ProgramId::advect_rk2_offset_ordered : p.advect;
    if (features & PF_FEATURE_OBSTACLES) {
        // Their stencils stop at SOLID cells (common/solid_walls.glsl).
        for (ProgramId* id : {&p.g2p, &p.g2p_ordered, &p.advect, &p.advect_ordered}) *id = with_solid_walls(*id);
    }
    return p;
}

pf_result Simulation::prepare_particle_passes(const pf_sim_params& params, uint32_t features, const char* fn) {
    if (pf_result r = p2g_.prepare(gl_, *runner_, params, log_, fn); r != PF_OK) return r;
    // With obstacles prepared (pf_sim_desc.prepared_features), their permutations are built too, so
    // that turning obstacles on builds nothing.
    for (uint32_t with : {features, features | (desc_.prepared_features & PF_FEATURE_OBSTACLES)}) {
        const ParticlePrograms programs = particle_programs(params, with);
        for (ProgramId id : {programs.grid_forces, programs.g2p, programs.g2p_ordered, programs.advect, programs.advect_ordered}) {
            if (std::string error = runner_->prepare(id); !error.empty())
                return log_.error(PF_ERROR_SHADER_COMPILE, std::string(fn) + ": " + error);
        }
        if (programs.g2p_ordered != programs.g2p) {
            if (std::string error = runner_->prepare(ProgramId::volume_correction_move_ordered); !error.empty())
                return log_.error(PF_ERROR_SHADER_COMPILE, std::string(fn) + ": " + error);
        }
    }
    if (params.transfer != PF_TRANSFER_APIC || affine_.bytes() != 0) return PF_OK;
    const uint64_t bytes = uint64_t(desc_.max_particles) * 48u;
    if (pf_result r = gl::check_storage_block(gl_, log_, bytes, std::string(fn) + ": APIC needs", "(48 per particle)",
                                              "lower max_particles");
        r != PF_OK)
        return r;
    gl::Buffer made(gl_, size_t(bytes), GL_DYNAMIC_COPY, "particle_affine", gl::Sizing::particles);
    if (pf_result r = gl::check_allocated(gl_, log_, std::string(fn) + ": allocating " + std::to_string(bytes >> 20) +
                                                         " MiB of APIC affine vectors");
        r != PF_OK)
        return r;
    affine_ = std::move(made);
    return PF_OK;
}

void Simulation::zero_affine(uint32_t first, uint32_t count) {
    if (affine_.bytes() == 0 || count == 0) return;
    if (first == 0) {
        runner_->fill(affine_, count * 12u, 0u, stat_.clear);
        return;
    }
    const std::vector<float> zeros(size_t(count) * 12, 0.0f);
    affine_.upload(size_t(first) * 48, zeros.size() * 4, zeros.data());
}

void Simulation::upload_uniforms(float dt) {
    SimUniforms& u = uniform_data_;
    u.grid = glm::ivec4(layout_.dims, int32_t(layout_.cells()));
    u.face_count = glm::ivec4(int32_t(layout_.face_count(0)), int32_t(layout_.face_count(1)), int32_t(layout_.face_count(2)),
                              int32_t(layout_.faces()));
    u.origin = glm::vec4(desc_.origin[0], desc_.origin[1], desc_.origin[2], 0.0f);
    u.gravity = glm::vec4(desc_.params.gravity[0], desc_.params.gravity[1], desc_.params.gravity[2], 0.0f);
    u.dx = desc_.cell_size;
    u.dt = dt;
    u.drift_dt = dt;
    u.density = desc_.density;
    u.max_speed = desc_.max_speed;
    const float weight_scale = p2g_.range().weight_scale();
    const float momentum_scale = weight_scale / desc_.max_speed;  // design.md §4.2
    u.momentum_scale = momentum_scale;
    u.weight_scale = weight_scale;
    u.inv_momentum_scale = 1.0f / momentum_scale;
    u.inv_weight_scale = 1.0f / weight_scale;
    u.flip_ratio = desc_.params.flip_ratio;
    u.particle_count = particle_count_;
    u.separation = desc_.params.separation;
    u.ghost_fluid = desc_.params.free_surface == PF_FREE_SURFACE_GHOST_FLUID ? 1u : 0u;
    u.rest_particles = float(desc_.fill_particles_per_cell);
    u.volume_correction = desc_.params.volume_correction;
    u.correction_reach = VolumeCorrection::reach_cells(desc_.params, dt);
    u.p2g_float_sums = p2g_.float_sums(desc_.params) ? 1u : 0u;
    uniforms_.upload(0, sizeof(SimUniforms), &u);
    if (gpu_count_) copy_count_to_uniforms();  // the kernels compare with the GPU's live count
}

VolumeCorrection::Inputs Simulation::correction_inputs() const {
    // The move reads in the P2G's order where G2P does (the particles have not moved since).
    const ParticlePrograms programs = particle_programs(desc_.params);
    const gl::Buffer* order = programs.g2p_ordered != programs.g2p ? g2p_order_ : nullptr;
    return {pos_, cell_type_, cell_count_, pressure_, face_fraction_, layout_.cells(), particle_count_, order};
}

void Simulation::set_drift(float seconds) {
    uniform_data_.drift_dt = seconds;
    uniforms_.upload(offsetof(SimUniforms, drift_dt), sizeof(float), &uniform_data_.drift_dt);
}

void Simulation::run_half_move() {
    update_substep_table();
    // The move stops before SOLID cells (common/particle_trace.glsl): the obstacles as they stand
    // now, on cells otherwise AIR (nothing else is known before P2G; classify rewrites them all).
    runner_->fill(cell_type_, uint32_t(layout_.cells()), PF_CELL_AIR, stat_.classify);
    run_effects(EffectStage::before_first_move);
    set_drift(0.5f * uniform_data_.dt);
    substep_.run(SubstepContext{}, "advect");
    set_drift(uniform_data_.dt);
}

void Simulation::run_substep(bool correct_volume, bool half_move) {
    update_substep_table();
    substep_.run(SubstepContext{correct_volume, half_move});
    cell_counts_current_ = true;
    counted_with_ = (desc_.features & PF_FEATURE_SINKS) ? PF_P2G_COUNT : desc_.params.p2g;
}

void Simulation::update_substep_table() {
    const SubstepShape shape{desc_.features, desc_.params.free_surface, desc_.params.volume_correction > 0.0f};
    if (substep_built_ && substep_shape_ == shape) return;
    build_substep_table();
    substep_shape_ = shape;
    substep_built_ = true;
}

std::vector<std::string> Simulation::substep_stage_names() {
    update_substep_table();
    return substep_.names();
}

void Simulation::build_substep_table() {
    SubstepTable& t = substep_;
    t.clear();
    const uint64_t cells = layout_.cells(), faces = layout_.faces();
    t.add("p2g", [this](const SubstepContext&) {
        p2g_.run(*runner_, desc_.params,
                 P2gBuffers{pos_, vel_, affine_, face_accum_, cell_count_, status_, particle_count_,
                            desc_.params.transfer == PF_TRANSFER_APIC, stat_.clear});
        g2p_order_ = p2g_.particle_order(desc_.params);
    });
    t.add("grid_forces", [this, faces](const SubstepContext&) {
        runner_->run({particle_programs(desc_.params).grid_forces, stat_.grid_forces, faces,
                      {{PF_SLOT_FACE_ACCUM, &face_accum_}, {PF_SLOT_FACE_VEL, &face_vel_},
                       {PF_SLOT_FACE_VEL_OLD, &face_vel_old_}, {PF_SLOT_FACE_FRACTION, &face_fraction_}}});
    });
    t.add("classify", [this, cells](const SubstepContext&) {
        runner_->run({ProgramId::classify, stat_.classify, cells,
                      {{PF_SLOT_CELL_COUNT, &cell_count_}, {PF_SLOT_CELL_TYPE, &cell_type_}}});
    });
    // The ghost-fluid words, once the cell kinds are final (the effects after classify
    // included: obstacles mark their cells SOLID).
    if (desc_.params.free_surface == PF_FREE_SURFACE_GHOST_FLUID) {
        t.add("free_surface", [this, cells](const SubstepContext&) {
            runner_->run({ProgramId::free_surface, stat_.free_surface, cells,
                          {{PF_SLOT_CELL_TYPE, &cell_type_}, {PF_SLOT_FACE_FRACTION, &face_fraction_}}});
        });
    }
    if (desc_.params.volume_correction > 0.0f) {
        t.add("volume_correction", [this](const SubstepContext& c) {
            if (!c.correct_volume) return;
            const VolumeCorrection::Inputs in = correction_inputs();
            // Its solve goes with the projection's (pressure_solve below): in the same passes where
            // its solver solves pairs, else alongside on buffers of its own, one pass of each after
            // a barrier, which per-kernel timing (every pass timed apart) cannot do: there, and
            // where both use one solver, the two go in turn.
            const bool alongside = solvers_in_use_.correction != solvers_in_use_.pressure && !runner_->kernel_timing();
            if (solvers_in_use_.correction && (correction_paired() || alongside)) {
                volume_correction_.setup(*runner_, in);
                correction_pending_ = true;
            } else {
                volume_correction_.run(*runner_, *solvers_in_use_.pressure, solve_params(), in);
            }
        });
    }
    // After every force on the faces and the obstacles' SOLID cells: which walls let go.
    const uint64_t wall_cells = layout_.wall_cells();
    t.add("wall_release", [this, wall_cells](const SubstepContext&) {
        runner_->run({ProgramId::wall_release, stat_.wall_release, wall_cells,
                      {{PF_SLOT_FACE_VEL, &face_vel_}, {PF_SLOT_CELL_TYPE, &cell_type_}, {PF_SLOT_PRESSURE, &pressure_}}});
    });
    t.add("pressure_setup", [this, cells](const SubstepContext&) {
        run_pressure_setup(*runner_, stat_.pressure_setup, pressure_);
        if (!hydrostatic_start_pending_) return;
        // One invocation per column along gravity's dominant axis (the kernel picks the same).
        const float* g = desc_.params.gravity;
        const float ax = std::abs(g[0]), ay = std::abs(g[1]), az = std::abs(g[2]);
        const int axis = (ax >= ay && ax >= az) ? 0 : (ay >= az ? 1 : 2);
        runner_->run({ProgramId::hydrostatic_start, stat_.hydrostatic_start, layout_.columns(axis),
                      {{PF_SLOT_CELL_TYPE, &cell_type_}, {PF_SLOT_PRESSURE, &pressure_}}});
        hydrostatic_start_pending_ = false;
    });
    t.add("pressure_solve", [this](const SubstepContext&) {
        // What this solver needed recently (a readback of another solver's step says nothing).
        const bool known = recent_solver_ == desc_.params.pressure_solver;
        const PressureProblem problem{cell_type_, rhs_, pressure_, status_, solve_params(),
                                      known ? recent_iterations_ : kUnknownIterations,
                                      known ? recent_later_iterations_ : kUnknownIterations,
                                      known && solver_residual_ <= desc_.params.pressure_tolerance,
                                      known ? solver_residual_ : -1.0f};
        if (!correction_pending_) {
            solvers_in_use_.pressure->solve(*runner_, problem);
            return;
        }
        // The volume correction's solve and the projection's read none of each other's buffers
        // (the correction's setup read the pressure before this solve changes it; its move
        // waits for both): issued in lockstep, one barrier a pair.
        correction_pending_ = false;
        const VolumeCorrection::Inputs in = correction_inputs();
        if (correction_paired()) {
            volume_correction_.solve_paired(*runner_, *solvers_in_use_.correction, solve_params(), in, problem);
            volume_correction_.move(*runner_, in);
            return;
        }
        PassRunner::Recorded correction, projection;
        {
            const PassRunner::Recording recording(*runner_, correction);
            volume_correction_.solve(*runner_, *solvers_in_use_.correction, solve_params(), in);
        }
        {
            const PassRunner::Recording recording(*runner_, projection);
            solvers_in_use_.pressure->solve(*runner_, problem);
        }
        runner_->run_interleaved(projection, correction);
        volume_correction_.move(*runner_, in);
    });
    t.add("velocity_update", [this](const SubstepContext&) {
        run_velocity_update(*runner_, stat_.velocity_update, pressure_);
    });
    t.add("extrapolate", [this, faces](const SubstepContext&) {
        valid_current_ = 0;
        for (uint32_t layer = 0; layer < extrapolation_layers(desc_.params, travel_cells_); ++layer) {
            runner_->run({ProgramId::extrapolate, stat_.extrapolate, faces,
                          {{PF_SLOT_FACE_VEL, &face_vel_}, {PF_SLOT_FACE_VALID, &face_valid_[valid_current_]},
                           {PF_SLOT_FACE_VALID_OUT, &face_valid_[1 - valid_current_]}}});
            valid_current_ = 1 - valid_current_;
        }
    });
    t.add("g2p", [this](const SubstepContext&) { run_g2p(); });
    t.add("advect", [this](const SubstepContext& c) {
        if (c.half_move) set_drift(0.5f * uniform_data_.dt);  // the step's last move: the next step sets it again
        run_advect();
    });
    // Effects that are on, after the core stage their stage follows (lowest feature bit first).
    const std::pair<EffectStage, const char*> hooks[] = {{EffectStage::after_grid_forces, "grid_forces"},
                                                         {EffectStage::after_classify, "classify"},
                                                         {EffectStage::after_velocity_update, "velocity_update"},
                                                         {EffectStage::after_advect, "advect"}};
    for (uint32_t i = 0; i < kEffectCount; ++i) {
        if (!(desc_.features & (1u << i))) continue;
        Effect* effect = effects_[i].get();
        for (const auto& [stage, after] : hooks) {
            if (!(effect->stages() & stage_bit(stage))) continue;
            const std::string name = std::string(effect->name()) + "/" + after;
            t.insert_after(after, name, [this, effect, stage = stage](const SubstepContext&) {
                effect->run(stage, *runner_, effect_buffers());
            });
        }
    }
}

void Simulation::run_metrics() {
    PassRunner& r = *runner_;
    // One fused pass over cells and particles (invocation i: cell i and particle i), then one
    // workgroup adds the partial sums in a fixed order and writes the status words.
    const uint64_t n = std::max<uint64_t>(layout_.cells(), particle_count_);
    const Bind partials{PF_SLOT_METRICS_PARTIALS, &metrics_partials_};
    r.run({ProgramId::metrics, stat_.metrics, n,
           {{PF_SLOT_PARTICLE_POS, &pos_}, {PF_SLOT_PARTICLE_VEL, &vel_}, {PF_SLOT_FACE_VEL, &face_vel_}, {PF_SLOT_CELL_COUNT, &cell_count_},
            {PF_SLOT_CELL_TYPE, &cell_type_}, partials}});
    r.run({ProgramId::metrics_finish, stat_.metrics, PF_WORKGROUP_SIZE, {partials, {PF_SLOT_STATUS, &status_}}, {},
           {Uniform::uint1(PF_LOC_METRICS_GROUPS, r.workgroups(n).total())}});
}

void Simulation::run_g2p() {
    PassRunner& r = *runner_;
    const uint32_t np = particle_count_;
    const Bind pos{PF_SLOT_PARTICLE_POS, &pos_}, vel{PF_SLOT_PARTICLE_VEL, &vel_},
        face_vel{PF_SLOT_FACE_VEL, &face_vel_}, status{PF_SLOT_STATUS, &status_};
    const ParticlePrograms programs = particle_programs(desc_.params);
    // In the P2G's tile order when this substep's P2G made one (same results, coherent reads).
    const bool ordered = g2p_order_ != nullptr && programs.g2p_ordered != programs.g2p;
    const gl::ProgramId g2p = ordered ? programs.g2p_ordered : programs.g2p;
    const Bind last = desc_.params.transfer == PF_TRANSFER_APIC ? Bind{PF_SLOT_PARTICLE_AFFINE, &affine_}
                                                                : Bind{PF_SLOT_FACE_VEL_OLD, &face_vel_old_};
    Bindings binds{pos, vel, face_vel, last, status};
    if (ordered) binds.add({PF_SLOT_PARTICLE_ORDER, g2p_order_});
    // FLIP limits a lone particle's delta on extrapolated faces: the P2G weights, the faces' cells.
    const bool flip = desc_.params.transfer != PF_TRANSFER_APIC && desc_.params.flip_ratio > 0.0f;
    if (flip) binds.add({PF_SLOT_G2P_FACE_ACCUM, &face_accum_});
    if (flip || (desc_.features & PF_FEATURE_OBSTACLES)) {
        // APIC's affine vectors hold PF_SLOT_CELL_TYPE there.
        const GLuint slot = desc_.params.transfer == PF_TRANSFER_APIC ? PF_SLOT_APIC_CELL_TYPE : PF_SLOT_CELL_TYPE;
        binds.add({slot, &cell_type_});
    }
    r.run({g2p, stat_.g2p, np, binds});
}

void Simulation::run_advect() {
    // The P2G's grouping holds until the particles move (G2P moves none).
    const gl::Buffer* order = g2p_order_;
    g2p_order_ = nullptr;
    PassRunner& r = *runner_;
    const uint32_t np = particle_count_;
    const ParticlePrograms programs = particle_programs(desc_.params);
    const bool ordered = order != nullptr && programs.advect_ordered != programs.advect;
    const gl::ProgramId advect = ordered ? programs.advect_ordered : programs.advect;
    // Euler and leapfrog move particles with their own (G2P) velocity, Runge-Kutta through the
    // grid's. All stop a move of several cells before an obstacle's SOLID cell
    // (common/particle_trace.glsl).
    Bindings binds{{PF_SLOT_PARTICLE_POS, &pos_}, {PF_SLOT_PARTICLE_VEL, &vel_}, {PF_SLOT_CELL_TYPE, &cell_type_}};
    if (advect != ProgramId::advect) binds.add({PF_SLOT_FACE_VEL, &face_vel_});
    if (ordered) binds.add({PF_SLOT_PARTICLE_ORDER, order});
    r.run({advect, stat_.advect, np, binds});
}

ProjectionCount Simulation::substeps_for(float frame_dt) const {
    // Nothing moves: one substep keeps the grid state current (unless an effect adds particles).
    bool adding = false;
    for (uint32_t i = 0; i < kEffectCount; ++i) adding = adding || ((desc_.features & (1u << i)) && effects_[i]->adds_particles());
    if (particle_count_ == 0 && !adding) return ProjectionCount{};
    float v_max = cfl_speed_;
    if (added_at_step_ > cfl_step_) v_max = std::max(v_max, added_speed_);
    const float* g = desc_.params.gravity;
    const float gravity = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    float accel = gravity;
    for (uint32_t i = 0; i < kEffectCount; ++i) {
        if (desc_.features & (1u << i)) v_max = std::max(v_max, effects_[i]->added_speed());
    }
    // Effects add accelerations (force fields, a moving frame) and impose speeds whatever was
    // measured (a wind's drag, an obstacle's surface pushing the liquid).
    // Some are stable only below a substep length of their own (surface tension's capillary waves).
    ProjectionDemand demand;
    demand.frame_dt = frame_dt;
    demand.cell_size = desc_.cell_size;
    demand.cfl = desc_.params.cfl;
    demand.max_projections = desc_.params.max_substeps;
    demand.speed = v_max;
    for (uint32_t i = 0; i < kEffectCount; ++i) {
        if (!(desc_.features & (1u << i))) continue;
        const CflBound bound = effects_[i]->cfl_bound(v_max);
        accel += bound.acceleration;
        demand.imposed_speed = std::max(demand.imposed_speed, bound.speed);
        if (bound.max_dt > 0.0f && (demand.max_dt == 0.0f || bound.max_dt < demand.max_dt)) demand.max_dt = bound.max_dt;
    }
    demand.acceleration = accel;
    // Leapfrog moves particles along straight lines at a large projection CFL; the strain limits
    // the compression that makes, and a long frame is cut into projections of at most half the
    // gravity time sqrt(dx / |g|), the unit of both.
    if (desc_.params.advection == PF_ADVECTION_LEAPFROG) {
        demand.strain = cfl_strain_;
        demand.longest_projection = kLeapfrogLongestProjection;
        demand.gravity = gravity;
    }
    return projections_for(demand);
}

pf_result Simulation::step(float frame_dt) {
    const auto t0 = std::chrono::steady_clock::now();
    gl::StateGuard guard(gl_, gl_state_);
    const gl::DebugGroup debug_group(gl_, "pflip/step");  // around the passes' own groups
    poll_status();
    take_lagged_status(int64_t(steps_) + 1);
    const ProjectionCount projections = substeps_for(frame_dt);
    if (projections.clamped) raise_flags(PF_FLAG_SUBSTEPS_CLAMPED);
    const BudgetPlan plan = fit_budget(gpu_budget_ms_, projections.count, desc_.params.pressure_iterations, measured_step());
    if (plan.fewer_projections) raise_flags(PF_FLAG_BUDGET_LIMITED);
    const uint32_t substeps = plan.projections;
    iteration_cap_ = plan.iteration_cap;
    travel_cells_ = projections.travel_cells * float(projections.count) / float(substeps);
    ++steps_;
    runner_->begin_step(steps_, substeps);

    // The max-speed word restarts every step; flag bits accumulate (a pf_push between steps
    // may have set one) until pf_clear_flags.
    const uint32_t zeros[5] = {0, 0, 0, 0, 0};  // max speed, solver iterations, residual, rounds
    static_assert(PF_STATUS_SOLVER_ITERATIONS == PF_STATUS_MAX_SPEED + 1 && PF_STATUS_SOLVER_RESIDUAL == PF_STATUS_MAX_SPEED + 2 &&
                      PF_STATUS_SOLVER_FIRST_ROUND == PF_STATUS_MAX_SPEED + 3 &&
                      PF_STATUS_SOLVER_LATER_ROUNDS == PF_STATUS_MAX_SPEED + 4,
                  "the per-step status words are contiguous");
    status_.upload(PF_STATUS_MAX_SPEED * 4, sizeof(zeros), zeros);
    upload_uniforms(frame_dt / float(substeps));
    step_substeps_ = substeps;
    begin_effects_step(frame_dt);
    run_count_stage(EffectStage::before_substeps);
    const bool correcting = desc_.params.volume_correction > 0.0f;
    const uint32_t ran = correcting ? 1u : 0u;
    status_.upload(PF_STATUS_CORRECTION_RAN * 4, sizeof ran, &ran);
    // What the correction's solves needed lately (as for the projection: a readback of another
    // solver's step says nothing).
    if (correcting) volume_correction_.begin_step(status_words_.data(), recent_solver_ == desc_.params.pressure_solver);
    // The volume correction: in the first substep, then again whenever another
    // VolumeCorrection::kInterval of simulated time has passed (compression grows with time,
    // not with frames: at 60 frames a second it runs once a step), or in every one
    // (VolumeCorrection::every_projection).
    const bool correct_always = VolumeCorrection::every_projection(desc_.params);
    const float substep_dt = frame_dt / float(substeps);
    float since_correction = 0.0f;
    // Leapfrog: the projections see the positions half a substep ahead of the velocities, and the
    // last move is half a substep, so the step ends with both at the frame's time.
    const bool leapfrog = desc_.params.advection == PF_ADVECTION_LEAPFROG;
    if (leapfrog) run_half_move();
    for (uint32_t s = 0; s < substeps; ++s) {
        const bool correct = s == 0 || correct_always || since_correction >= VolumeCorrection::kInterval;
        if (correct) since_correction = 0.0f;
        run_substep(correct, leapfrog && s + 1 == substeps);
        since_correction += substep_dt;
    }
    if (correcting) volume_correction_.report(*runner_, status_);
    run_count_stage(EffectStage::after_substeps);
    run_metrics();
    runner_->end_step();
    end_effects_step();

    // Status readback ring: copy now; the next step takes this one in (waiting only if the GPU
    // has not finished it by then), pf_get_stats whenever its fence has passed.
    const int slot = int(steps_ % kReadbackSlots);
    if (readback_.pending(slot)) read_status_slot(slot);  // taken in already (kStatusLag); never dropped
    runner_->copy(status_, readback_.buffer(slot), PF_STATUS_WORDS * 4);
    readback_.fence(slot);
    // Each readback carries the flags raised since the previous one (the sticky union is the
    // host's flags_), so a readback tells which step overflowed (the P2G range widening).
    const uint32_t no_flags = 0;
    status_.upload(PF_STATUS_FLAGS * 4, 4, &no_flags);
    fence_step_[slot] = steps_;
    fence_solver_[slot] = desc_.params.pressure_solver;
    fence_capped_[slot] = iteration_cap_ < desc_.params.pressure_iterations;
    fence_added_[slot] = added_total_;

    // Engines may read the particle buffers as vertex data, SSBOs or by copying, and draw them
    // through the draw_indirect records the GPU wrote (emitters, sinks, whitewater).
    gl_.MemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT |
                      GL_BUFFER_UPDATE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
    last_substeps_ = substeps;
    last_cpu_ms_ = std::chrono::duration<float, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return PF_OK;
}

template <typename Passes>
void Simulation::run_one_step_for_test(float dt, Passes&& passes) {
    gl::StateGuard guard(gl_, gl_state_);
    ++steps_;
    runner_->begin_step(steps_, 1);
    upload_uniforms(dt);
    step_substeps_ = 1;
    begin_effects_step(dt);
    passes();
    runner_->end_step();
    end_effects_step();
    gl_.MemoryBarrier(GL_ALL_BARRIER_BITS);
}

pf_result Simulation::run_substep_for_test(float dt) {
    run_one_step_for_test(dt, [&] { run_substep(false); });
    return PF_OK;
}

pf_result Simulation::run_effect_stages_for_test(std::initializer_list<EffectStage> stages, float dt) {
    run_one_step_for_test(dt, [&] {
        EffectBuffers buffers = effect_buffers();
        buffers.projector = nullptr;  // the effects' own passes alone
        for (EffectStage stage : stages) {
            for (uint32_t i = 0; i < kEffectCount; ++i) {
                if ((desc_.features & (1u << i)) && (effects_[i]->stages() & stage_bit(stage)))
                    effects_[i]->run(stage, *runner_, buffers);
            }
        }
    });
    return PF_OK;
}

pf_result Simulation::run_volume_correction_for_test() {
    run_one_step_for_test(0.01f, [&] {
        volume_correction_.run(*runner_, *solvers_in_use_.pressure, desc_.params, correction_inputs());
    });
    return PF_OK;
}

pf_result Simulation::run_metrics_for_test() {
    run_one_step_for_test(0.01f, [&] { run_metrics(); });
    return PF_OK;
}

std::vector<float> Simulation::read_volume_potential() const {
    gl::StateGuard guard(gl_, gl_state_);
    std::vector<float> q(static_cast<size_t>(layout_.cells()), 0.0f);
    volume_correction_.potential().download(0, q.size() * 4, q.data());
    return q;
}

pf_result Simulation::solve_for_test(const std::vector<uint32_t>& cell_type, const std::vector<float>& rhs,
                                     std::vector<float>& pressure) {
    if (cell_type.size() != size_t(layout_.cells()) || rhs.size() != size_t(layout_.cells()) || pressure.size() != size_t(layout_.cells()))
        return PF_ERROR_INVALID_ARGUMENT;
    gl::StateGuard guard(gl_, gl_state_);
    cell_type_.upload(0, cell_type.size() * 4, cell_type.data());
    rhs_.upload(0, rhs.size() * 4, rhs.data());
    pressure_.upload(0, pressure.size() * 4, pressure.data());
    const uint32_t zeros[2] = {0, 0};
    status_.upload(PF_STATUS_SOLVER_ITERATIONS * 4, sizeof(zeros), zeros);
    run_one_step_for_test(0.01f, [&] {
        solvers_in_use_.pressure->solve(*runner_, PressureProblem{cell_type_, rhs_, pressure_, status_, desc_.params});
    });
    pressure_.download(0, pressure.size() * 4, pressure.data());
    return PF_OK;
}

pf_result Simulation::solve_two_for_test(const std::vector<uint32_t>& cell_type, const std::vector<float> (&rhs)[2],
                                         std::vector<float> (&pressure)[2], bool paired, uint32_t (&iterations)[2]) {
    const size_t n = size_t(layout_.cells());
    if (!solvers_in_use_.correction || cell_type.size() != n) return PF_ERROR_INVALID_ARGUMENT;
    for (int k = 0; k < 2; ++k) {
        if (rhs[k].size() != n || pressure[k].size() != n) return PF_ERROR_INVALID_ARGUMENT;
    }
    gl::StateGuard guard(gl_, gl_state_);
    cell_type_.upload(0, n * 4, cell_type.data());
    gl::Buffer rhs_buffers[2], x[2], reports[2];
    const std::vector<uint32_t> zeros(PF_STATUS_WORDS, 0u);
    for (int k = 0; k < 2; ++k) {
        rhs_buffers[k] = gl::Buffer(gl_, n * 4, GL_DYNAMIC_COPY, "test_rhs");
        rhs_buffers[k].upload(0, n * 4, rhs[k].data());
        x[k] = gl::Buffer(gl_, n * 4, GL_DYNAMIC_COPY, "test_x");
        x[k].upload(0, n * 4, pressure[k].data());
        reports[k] = gl::Buffer(gl_, zeros.size() * 4, GL_DYNAMIC_COPY, "test_report");
        reports[k].upload(0, zeros.size() * 4, zeros.data());
    }
    const pf_sim_params params[2] = {desc_.params, VolumeCorrection::solve_params(desc_.params)};
    const PressureProblem first{cell_type_, rhs_buffers[0], x[0], reports[0], params[0]};
    const PressureProblem second{cell_type_, rhs_buffers[1], x[1], reports[1], params[1]};
    PressureSolver& solver = *solvers_in_use_.correction;
    run_one_step_for_test(0.01f, [&] {
        if (paired) {
            solver.solve_pair(*runner_, first, second);
        } else {
            solver.solve(*runner_, first);
            solver.solve(*runner_, second);
        }
    });
    for (int k = 0; k < 2; ++k) {
        x[k].download(0, n * 4, pressure[k].data());
        reports[k].download(PF_STATUS_SOLVER_ITERATIONS * 4, 4, &iterations[k]);
    }
    return PF_OK;
}

pf_result Simulation::set_ordered_g2p_face_bytes_for_test(uint64_t bytes) {
    ordered_g2p_face_bytes_ = bytes;
    return prepare_particle_passes(desc_.params, "set_ordered_g2p_face_bytes_for_test");
}

bool Simulation::one_cell_reductions() const {
    return SolveControl::orbits(layout_.dims) <= one_cell_reduction_orbits_;
}

pf_result Simulation::set_one_cell_reduction_orbits_for_test(uint64_t orbits) {
    gl::StateGuard guard(gl_, gl_state_);
    // An error left pending (a test's own GL calls) would be mistaken for the allocation's below.
    while (gl_.GetError() != GL_NO_ERROR) {
    }
    one_cell_reduction_orbits_ = orbits;
    for (auto* slots : {&solvers_, &correction_solvers_})
        for (std::unique_ptr<PressureSolver>& solver : *slots) solver.reset();
    for (auto& slot : pair_solvers_) slot.reset();
    return solvers_for(desc_.params, "set_one_cell_reduction_orbits_for_test", &solvers_in_use_);
}

pf_result Simulation::run_g2p_and_advect_for_test(float dt) {
    update_substep_table();
    run_one_step_for_test(dt, [&] { substep_.run(SubstepContext{}, "g2p"); });
    return PF_OK;
}

void Simulation::poll_status() const {
    for (int s = 0; s < kReadbackSlots; ++s) {
        if (readback_.arrived(s)) read_status_slot(s);
    }
}

void Simulation::take_lagged_status(int64_t step) {
    const int64_t measured = step - int64_t(kStatusLag);
    const int s = int(((measured % kReadbackSlots) + kReadbackSlots) % kReadbackSlots);
    if (readback_.pending(s) && int64_t(fence_step_[s]) == measured) read_status_slot(s);  // the GPU is that far behind: wait
    const StepStatus& got = received_[s];
    if (!got.valid || got.step != measured) return;  // no such step (the first ones)
    cfl_speed_ = got.max_speed;
    cfl_strain_ = got.strain;
    cfl_step_ = measured;
    // A fixed-point sum overflowed in a step run at today's range: widen it from this step on
    // (the overflowing step's result is flagged; integer sums stay deterministic).
    if (got.flags & PF_FLAG_P2G_OVERFLOW) p2g_.range().widen_after_overflow(measured, step, log_);
}

void Simulation::read_status_slot(int s) const {
    uint32_t words[PF_STATUS_WORDS] = {};
    {
        gl::StateGuard guard(gl_, gl_state_);
        readback_.take(s, words, sizeof(words));  // waits for the copy if it has not run yet
    }
    StepStatus& got = received_[s];
    got.valid = 1;
    got.step = int64_t(fence_step_[s]);
    std::memcpy(&got.max_speed, &words[PF_STATUS_MAX_SPEED], sizeof(float));
    std::memcpy(&got.strain, &words[PF_STATUS_STRAIN], sizeof(float));
    got.flags = words[PF_STATUS_FLAGS];
    // The GPU's live count then, plus what was added since, bounds today's count (sinks
    // only lower it).
    if (gpu_count_) {
        const uint64_t bound = uint64_t(words[PF_STATUS_PARTICLE_COUNT]) + (added_total_ - fence_added_[s]);
        if (bound < particle_count_) particle_count_ = uint32_t(bound);
    }
    if (fence_step_[s] > flags_cleared_at_step_) raise_flags(words[PF_STATUS_FLAGS]);
    // A solve the budget cut that stopped above its tolerance did less than params ask.
    float residual = 0.0f;
    std::memcpy(&residual, &words[PF_STATUS_SOLVER_RESIDUAL], sizeof(float));
    if (fence_capped_[s] && fence_step_[s] > flags_cleared_at_step_ && residual > desc_.params.pressure_tolerance)
        raise_flags(PF_FLAG_BUDGET_LIMITED);
    if (fence_step_[s] > status_step_) {
        status_step_ = fence_step_[s];
        std::copy(std::begin(words), std::end(words), status_words_.begin());
        std::memcpy(&gpu_max_speed_, &words[PF_STATUS_MAX_SPEED], sizeof(float));
        solver_iterations_ = words[PF_STATUS_SOLVER_ITERATIONS];
        recent_iterations_ = words[PF_STATUS_SOLVER_FIRST_ROUND];
        recent_later_iterations_ = words[PF_STATUS_SOLVER_LATER_ROUNDS];
        recent_solver_ = fence_solver_[s];
        std::memcpy(&solver_residual_, &words[PF_STATUS_SOLVER_RESIDUAL], sizeof(float));
        Metrics m;
        std::memcpy(&m.divergence_l2, &words[PF_STATUS_DIVERGENCE_L2], sizeof(float));
        std::memcpy(&m.divergence_max, &words[PF_STATUS_DIVERGENCE_MAX], sizeof(float));
        std::memcpy(&m.kinetic_energy, &words[PF_STATUS_KINETIC_ENERGY], sizeof(float));
        std::memcpy(&m.particle_volume, &words[PF_STATUS_PARTICLE_VOLUME], sizeof(float));
        float height_energy = 0.0f;
        std::memcpy(&height_energy, &words[PF_STATUS_POTENTIAL_ENERGY], sizeof(float));
        const uint32_t live = words[PF_STATUS_PARTICLE_COUNT];
        m.potential_energy = float(double(height_energy) - double(live) * lowest_potential_per_particle());
        m.fluid_cells = words[PF_STATUS_FLUID_CELLS];
        std::memcpy(&m.interior_density, &words[PF_STATUS_INTERIOR_DENSITY], sizeof(float));
        std::memcpy(&m.strain, &words[PF_STATUS_STRAIN], sizeof(float));
        // Mass over density: the particles' volume at rest density, divided by the density they
        // hold where no free surface thins the count (docs/design.md §4.11).
        const double rest_volume = double(live) / desc_.fill_particles_per_cell * std::pow(double(desc_.cell_size), 3);
        m.liquid_volume = float(m.interior_density > 0.0f ? rest_volume / m.interior_density : rest_volume);
        metrics_ = m;
        readback_count_ = live;
        whitewater_count_ = words[PF_STATUS_WHITEWATER_COUNT];
        viscosity_iterations_ = words[PF_STATUS_VISCOSITY_ITERATIONS];
        std::memcpy(&viscosity_residual_, &words[PF_STATUS_VISCOSITY_RESIDUAL], sizeof(float));
        // The drifts' reference: the first step measured since the particles last changed.
        if (!metrics_first_set_ && fence_step_[s] >= metrics_epoch_step_) {
            metrics_first_ = m;
            metrics_first_set_ = true;
        }
        // Lost volume: the liquid volume (mass over density) against the particles' rest
        // volume. Only compression of the bulk lowers it (the capped count sum of
        // particle_volume also falls where counts merely spread, and a liquid at rest density
        // raised the flag), and unlike the drift it needs no earlier measurement (a 1 s frame
        // compresses a dam break before the first one).
        if (fence_step_[s] > flags_cleared_at_step_ && rest_volume > 0.0 &&
            double(m.liquid_volume) / rest_volume - 1.0 < -double(desc_.params.volume_loss_limit))
            raise_flags(PF_FLAG_VOLUME_LOST);
        // Mechanical energy against its reference: without input (gravity does no net work
        // on a closed system; the projection and the walls only remove energy) it can only
        // fall, so a gain beyond the limit is numerical. The scale has a floor of every
        // particle lifted one cell under 9.81 m/s^2, so a liquid at rest near zero energy
        // does not raise it for rounding.
        if (!energy_first_set_ && fence_step_[s] >= energy_epoch_step_) {
            energy_first_ = double(m.kinetic_energy) + m.potential_energy;
            energy_first_set_ = true;
        }
        if (energy_first_set_ && fence_step_[s] > flags_cleared_at_step_) {
            const double floor = double(live) * particle_mass() * 9.81 * desc_.cell_size;
            const double scale = std::max(energy_first_, floor);
            if (double(m.kinetic_energy) + m.potential_energy - energy_first_ > double(desc_.params.energy_gain_limit) * scale)
                raise_flags(PF_FLAG_ENERGY_GAINED);
        }
    }
}

pf_result Simulation::add_particles(const float* xyz, const float* vel, uint32_t n) {
    if (n == 0) return PF_OK;
    live_count();  // while the GPU keeps the count: wait for it, the new particles go right after
    std::vector<float> pos4(size_t(n) * 4, 0.0f), vel4(size_t(n) * 4, 0.0f);
    float fastest = 0.0f;
    for (uint32_t i = 0; i < n; ++i) {
        for (int a = 0; a < 3; ++a) {
            pos4[size_t(i) * 4 + a] = xyz[size_t(i) * 3 + a];
            vel4[size_t(i) * 4 + a] = vel ? vel[size_t(i) * 3 + a] : 0.0f;
        }
        const float* v = &vel4[size_t(i) * 4];
        fastest = std::max(fastest, std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
    }
    {
        gl::StateGuard guard(gl_, gl_state_);
        pos_.upload(size_t(particle_count_) * 16, size_t(n) * 16, pos4.data());
        vel_.upload(size_t(particle_count_) * 16, size_t(n) * 16, vel4.data());
        zero_affine(particle_count_, n);  // APIC: a new particle starts as plain PIC (C = 0)
    }
    particle_count_ += n;
    added_total_ += n;
    {
        gl::StateGuard guard(gl_, gl_state_);
        write_count_record(particle_count_);
    }
    restart_volume_reference();
    hydrostatic_start_pending_ = true;  // the new particles' cells hold p = 0
    added_speed_ = (added_at_step_ > cfl_step_) ? std::max(added_speed_, fastest) : fastest;
    added_at_step_ = int64_t(steps_) + 1;
    return PF_OK;
}

void Simulation::restart_volume_reference() {
    cell_counts_current_ = false;  // particles were added: their cells are not counted yet
    metrics_first_set_ = false;
    metrics_epoch_step_ = steps_ + 1;  // readbacks of earlier steps measured other particles
    restart_energy_reference();
}

void Simulation::restart_energy_reference() {
    energy_first_set_ = false;
    energy_epoch_step_ = steps_ + 1;
}

double Simulation::particle_mass() const { return double(desc_.density) * particle_volume(); }

double Simulation::particle_volume() const {
    return std::pow(double(desc_.cell_size), 3) / desc_.fill_particles_per_cell;
}

double Simulation::lowest_potential_per_particle() const {
    // m * min over the domain's corners of -g . (corner - origin): the potential's zero.
    double lowest = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        double h = 0.0;
        for (int a = 0; a < 3; ++a)
            if ((corner >> a) & 1) h -= double(desc_.params.gravity[a]) * desc_.cell_size * desc_.grid_size[a];
        lowest = std::min(lowest, h);
    }
    return particle_mass() * lowest;
}

pf_result Simulation::fill_box(const float lo[3], const float hi[3], const float vel[3]) {
    live_count();  // the capacity check needs the exact count
    FillLattice lattice{desc_, lo, hi};
    const uint64_t n = lattice.count();
    if (n == 0) return log_.error(PF_ERROR_INVALID_ARGUMENT, "pf_fill_box: the box is empty or does not overlap the domain");
    if (uint64_t(particle_count_) + n > desc_.max_particles) {
        return log_.error(PF_ERROR_CAPACITY, "pf_fill_box: the box holds " + std::to_string(n) +
                                                 " particles but only " +
                                                 std::to_string(desc_.max_particles - particle_count_) +
                                                 " slots are free (max_particles = " +
                                                 std::to_string(desc_.max_particles) + ")");
    }
    std::vector<float> xyz;
    lattice.generate(desc_.seed, fill_calls_++, xyz);
    std::vector<float> v;
    if (vel) {
        v.resize(xyz.size());
        for (size_t i = 0; i < v.size(); ++i) v[i] = vel[i % 3];
    }
    return add_particles(xyz.data(), vel ? v.data() : nullptr, uint32_t(xyz.size() / 3));
}

void Simulation::raise_flags(uint32_t bits) const {
    const uint32_t fresh = bits & ~flags_;
    flags_ |= bits;
    // One warning per flag until pf_clear_flags: a PF_OK step whose result is not trustworthy
    // must say so without flooding the log every frame.
    struct Text {
        uint32_t bit;
        const char* text;
    };
    static constexpr Text kTexts[] = {
        {PF_FLAG_P2G_OVERFLOW, "a fixed-point particle-to-grid sum overflowed (too many particles on one grid sample): "
                               "that step's velocity there is wrong (particles there are clamped to max_speed) and "
                               "the range is widened for the following steps; PF_P2G_FLOAT_ATOMIC cannot overflow "
                               "(PF_FLAG_P2G_OVERFLOW)"},
        {PF_FLAG_NONFINITE, "a non-finite particle velocity was found and set to 0 (PF_FLAG_NONFINITE)"},
        {PF_FLAG_SPEED_CLAMPED, "a particle exceeded desc.max_speed and was slowed to it (PF_FLAG_SPEED_CLAMPED)"},
        {PF_FLAG_SUBSTEPS_CLAMPED, "the frame needs more than params.max_substeps substeps: particles cross more "
                                   "than params.cfl cells per substep, so the step is less accurate, or an effect's "
                                   "own limit (surface tension's) is longer than the substeps allow, so it acts "
                                   "weaker (PF_FLAG_SUBSTEPS_CLAMPED)"},
        {PF_FLAG_ENERGY_GAINED, "the liquid's mechanical energy rose more than params.energy_gain_limit above its "
                                "reference without input (pf_stats.energy_drift): the step is numerically unsound, "
                                "typically an unconverged pressure solve; a converged solver (PF_QUALITY_BALANCED) "
                                "or smaller frame times fix it (PF_FLAG_ENERGY_GAINED)"},
        {PF_FLAG_VOLUME_LOST, "the liquid lost more than params.volume_loss_limit of its rest volume to compression "
                              "(pf_stats.liquid_volume); consider a converged pressure solver, volume "
                              "correction or smaller frame times (PF_FLAG_VOLUME_LOST)"},
        {PF_FLAG_EMITTERS_FULL, "the emitters wanted more particles than desc.max_particles leaves room for: "
                                "emission stopped at the capacity (PF_FLAG_EMITTERS_FULL)"},
        {PF_FLAG_WHITEWATER_FULL, "the liquid made more whitewater than pf_whitewater.capacity holds: the rest was "
                                  "not made; raise the capacity or lower the rates (PF_FLAG_WHITEWATER_FULL)"},
        {PF_FLAG_BUDGET_LIMITED, "to stay within the GPU budget (pf_set_gpu_budget) a step took fewer substeps than "
                                 "params.cfl asks for or stopped a pressure solve above params.pressure_tolerance: "
                                 "the step is less accurate (PF_FLAG_BUDGET_LIMITED)"},
    };
    for (const Text& t : kTexts)
        if (fresh & t.bit) log_.warning(std::string("pf_step: ") + t.text);
}

void Simulation::clear_flags() {
    flags_ = 0;
    flags_cleared_at_step_ = steps_;  // readbacks still in flight predate the clear
    gl::StateGuard guard(gl_, gl_state_);
    const uint32_t zero = 0;
    status_.upload(PF_STATUS_FLAGS * 4, 4, &zero);
}

pf_result Simulation::clear_particles() {
    gl::StateGuard guard(gl_, gl_state_);
    restart_volume_reference();
    particle_count_ = 0;  // freed slots' APIC affine vectors are zeroed when add_particles reuses them
    write_count_record(0);
    runner_->fill(pressure_, uint32_t(layout_.cells()), 0u, stat_.clear);
    added_speed_ = 0.0f;
    gpu_max_speed_ = 0.0f;
    return PF_OK;
}

pf_result Simulation::push(const float center[3], float radius, const float dv[3]) {
    if (particle_count_ == 0) return PF_OK;
    gl::StateGuard guard(gl_, gl_state_);
    if (std::string error = runner_->prepare(ProgramId::push); !error.empty())
        return log_.error(PF_ERROR_SHADER_COMPILE, "pf_push: " + error);
    // Between steps: neither timed nor counted in a step's statistics.
    runner_->run({ProgramId::push, stat_.g2p, particle_count_,
                  {{PF_SLOT_PARTICLE_POS, &pos_}, {PF_SLOT_PARTICLE_VEL, &vel_}, {PF_SLOT_STATUS, &status_}},
                  {},
                  {Uniform::vec4(PF_LOC_PUSH_CENTER_RADIUS, center[0], center[1], center[2], radius),
                   Uniform::vec4(PF_LOC_PUSH_DV_MAX_SPEED, dv[0], dv[1], dv[2], desc_.max_speed),
                   Uniform::uint1(PF_LOC_PUSH_COUNT, particle_count_)}});
    // The push may make particles faster than the last readback knew: CFL must see it.
    const float known = added_at_step_ > cfl_step_ ? std::max(added_speed_, cfl_speed_) : cfl_speed_;
    added_speed_ = std::min(desc_.max_speed, known + std::sqrt(dv[0] * dv[0] + dv[1] * dv[1] + dv[2] * dv[2]));
    added_at_step_ = int64_t(steps_) + 1;
    restart_energy_reference();  // the push is an input of energy
    gl_.MemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    return PF_OK;
}

void Simulation::warn_about_free_surface(const pf_sim_params& params, const char* fn) const {
    const bool stationary =
        params.pressure_solver == PF_PRESSURE_SOLVER_JACOBI || params.pressure_solver == PF_PRESSURE_SOLVER_RBGS;
    if (params.free_surface == PF_FREE_SURFACE_GHOST_FLUID && stationary)
        log_.warning(std::string(fn) + ": the ghost-fluid free surface with a stationary solver (Jacobi, RBGS) that stops "
                                       "before converging adds energy (40 Jacobi sweeps: 4.4 times a standing wave's "
                                       "energy, docs/accuracy.md); use a Krylov solver (MGPCG)");
}

pf_result Simulation::set_params(const pf_sim_params& params) {
    // Everything the new parameters need is built first, so a failure changes nothing.
    gl::StateGuard guard(gl_, gl_state_);
    if (pf_result r = prepare_particle_passes(params, "pf_set_params"); r != PF_OK) return r;
    SolversInUse solvers;
    if (pf_result r = solvers_for(params, "pf_set_params", &solvers); r != PF_OK) return r;
    // Affine vectors left from an earlier APIC period do not belong to today's velocities:
    // entering APIC starts every particle from C = 0 (plain PIC for its first transfer).
    if (params.transfer == PF_TRANSFER_APIC && desc_.params.transfer != PF_TRANSFER_APIC)
        zero_affine(0, particle_count_);
    solvers_in_use_ = solvers;
    desc_.params = params;
    warn_about_free_surface(params, "pf_set_params");
    for (auto& effect : effects_) effect->params_changed(params);
    restart_energy_reference();  // gravity may have changed: the old total is not comparable
    return PF_OK;
}

pf_result Simulation::prepare_features(uint32_t features, const char* fn) {
    // Programs only: the effects' buffers and statistics entries wait for pf_set_features (init),
    // which then finds the programs built.
    for (uint32_t i = 0; i < kEffectCount; ++i) {
        if (!(features & (1u << i))) continue;
        if (pf_result r = effects_[i]->prepare_programs(*runner_, log_, fn); r != PF_OK) return r;
    }
    return PF_OK;
}

pf_result Simulation::set_features(uint32_t features, const char* fn) {
    // Effects turned on for the first time are built first, so a failure changes nothing.
    gl::StateGuard guard(gl_, gl_state_);
    for (uint32_t i = 0; i < kEffectCount; ++i) {
        const uint32_t bit = 1u << i;
        if (!(features & bit) || (effects_ready_ & bit)) continue;
        if (pf_result r = effects_[i]->init(gl_, *runner_, log_, fn); r != PF_OK) return r;
        if (pf_result r = gl::check_allocated(gl_, log_, std::string(fn) + ": allocating an effect's buffers"); r != PF_OK)
            return r;
        effects_ready_ |= bit;
    }
    // G2P and the traces have permutations of their own with obstacles.
    if ((features ^ desc_.features) & PF_FEATURE_OBSTACLES) {
        if (pf_result r = prepare_particle_passes(desc_.params, features, fn); r != PF_OK) return r;
    }
    for (uint32_t i = 0; i < kEffectCount; ++i) {
        const uint32_t bit = 1u << i;
        if ((features & bit) && !(desc_.features & bit)) effects_[i]->turned_on();
    }
    const bool gpu_count = (features & kGpuCountFeatures) != 0;
    // The count record is current in both modes; leaving GPU mode makes the host count exact.
    if (gpu_count_ && !gpu_count) live_count();
    gpu_count_ = gpu_count;
    desc_.features = features;
    return PF_OK;
}

void Simulation::begin_effects_step(float frame_dt) {
    bool work = false, changes = false;
    uint64_t added = 0;
    const FrameInfo frame{frame_dt, steps_, particle_volume(),
                          status_words_.data(), status_step_};
    for (uint32_t i = 0; i < kEffectCount; ++i) {
        if (!(desc_.features & (1u << i))) continue;
        effects_[i]->begin_frame(frame);
        effects_[i]->begin_step();
        work = work || effects_[i]->does_work();
        changes = changes || effects_[i]->changes_particles();
        added += effects_[i]->particles_added();
    }
    if (work) restart_energy_reference();  // energy put in by an effect is not a numerical gain
    if (changes) {
        // The drifts compare like with like: a new reference once the particles changed. The
        // energy reference stays (removing particles only lowers the energy).
        metrics_first_set_ = false;
        metrics_epoch_step_ = steps_ + 1;
    }
    if (added > 0) {
        // Passes cover the slots emitters may fill; the GPU decides how many they do.
        particle_count_ = uint32_t(std::min<uint64_t>(uint64_t(particle_count_) + added, desc_.max_particles));
        added_total_ += added;
        float fastest = 0.0f;
        for (uint32_t i = 0; i < kEffectCount; ++i) {
            if (desc_.features & (1u << i)) fastest = std::max(fastest, effects_[i]->added_speed());
        }
        added_speed_ = (added_at_step_ > cfl_step_) ? std::max(added_speed_, fastest) : fastest;
        added_at_step_ = int64_t(steps_);
    }
}

EffectBuffers Simulation::effect_buffers() const {
    const bool apic = desc_.params.transfer == PF_TRANSFER_APIC;
    return EffectBuffers{pos_,       vel_,          face_accum_, p2g_float_sums(), face_vel_, face_vel_old_,
                         face_fraction_, cell_type_, count_record_, status_,     apic ? &affine_ : nullptr,
                         pressure_,  particle_count_, layout_, step_substeps_, this};
}

void Simulation::project(PassRunner& runner, const gl::Buffer& potential, const gl::Buffer& report, StatId stat,
                         uint32_t recent_iterations, float recent_residual) const {
    const PassRunner::StatScope as_effect(runner, stat);
    run_pressure_setup(runner, stat, potential);
    pf_sim_params params = desc_.params;
    params.separation = 0;  // a correction of either sign, not a pressure
    solvers_in_use_.pressure->solve(runner, PressureProblem{cell_type_, rhs_, potential, report, params, recent_iterations,
                                           kUnknownIterations,
                                           recent_residual >= 0.0f && recent_residual <= params.pressure_tolerance,
                                           recent_residual});
    run_velocity_update(runner, stat, potential);
}

void Simulation::run_pressure_setup(PassRunner& runner, StatId stat, const gl::Buffer& pressure) const {
    runner.run({ProgramId::pressure_setup, stat, layout_.cells(),
                {{PF_SLOT_FACE_VEL, &face_vel_}, {PF_SLOT_CELL_TYPE, &cell_type_}, {PF_SLOT_RHS, &rhs_},
                 {PF_SLOT_PRESSURE, &pressure}}});
}

void Simulation::run_velocity_update(PassRunner& runner, StatId stat, const gl::Buffer& pressure) const {
    runner.run({ProgramId::velocity_update, stat, layout_.faces(),
                {{PF_SLOT_FACE_VEL, &face_vel_}, {PF_SLOT_CELL_TYPE, &cell_type_}, {PF_SLOT_PRESSURE, &pressure},
                 {PF_SLOT_FACE_VALID_OUT, &face_valid_[0]}, {PF_SLOT_FACE_FRACTION, &face_fraction_}}});
}

void Simulation::end_effects_step() {
    for (uint32_t i = 0; i < kEffectCount; ++i) {
        if (desc_.features & (1u << i)) effects_[i]->end_step(*runner_, steps_);
    }
}

void Simulation::run_effects(EffectStage stage) {
    if (desc_.features == 0) return;
    const EffectBuffers buffers = effect_buffers();
    for (uint32_t i = 0; i < kEffectCount; ++i) {
        if (desc_.features & (1u << i)) effects_[i]->run(stage, *runner_, buffers);
    }
}

void Simulation::run_count_stage(EffectStage stage) {
    run_effects(stage);
    if (gpu_count_) copy_count_to_uniforms();
}

pf_result Simulation::read_particles(uint32_t first, uint32_t count, float* xyz, float* vel) const {
    std::vector<float> tmp(size_t(count) * 4);
    gl::StateGuard guard(gl_, gl_state_);
    const std::pair<const gl::Buffer*, float*> outs[] = {{&pos_, xyz}, {&vel_, vel}};
    for (const auto& [buffer, out] : outs) {
        if (!out) continue;
        buffer->download(size_t(first) * 16, tmp.size() * 4, tmp.data());
        for (uint32_t i = 0; i < count; ++i) {
            for (int a = 0; a < 3; ++a) out[size_t(i) * 3 + a] = tmp[size_t(i) * 4 + a];
        }
    }
    return PF_OK;
}

pf_result Simulation::request_particles(uint32_t first, uint32_t count, uint32_t* ticket) {
    gl::StateGuard guard(gl_, gl_state_);
    return requests_->request(pos_, vel_, first, count, ticket, log_);
}

pf_result Simulation::poll_particles(uint32_t ticket, float* xyz, float* vel) {
    gl::StateGuard guard(gl_, gl_state_);
    return requests_->poll(ticket, xyz, vel, log_);
}

void Simulation::gl_buffers(pf_gl_buffers& out) const {
    out.positions = pos_.id();
    out.velocities = vel_.id();
    out.count = particle_count_;
    out.stride = 16;
    out.draw_indirect = count_record_.id();
}

void Simulation::stats(pf_stats& out) const {
    gl::StateGuard guard(gl_, gl_state_);
    poll_status();
    runner_->poll_timers();
    out = pf_stats{};
    out.particle_count = gpu_count_ ? readback_count_ : particle_count_;
    out.max_particles = desc_.max_particles;
    out.gpu_memory_bytes = memory_.bytes;
    out.gpu_particle_bytes = memory_.particle_bytes;
    out.whitewater_count = (desc_.features & PF_FEATURE_WHITEWATER) ? whitewater_count_ : 0;
    const bool viscous = (desc_.features & PF_FEATURE_VISCOSITY) != 0;
    out.viscosity_iterations = viscous ? viscosity_iterations_ : 0;
    out.viscosity_residual = viscous ? viscosity_residual_ : 0.0f;
    out.steps = steps_;
    out.substeps = last_substeps_;
    out.flags = flags_;
    out.max_speed = gpu_max_speed_;
    out.solver_iterations = solver_iterations_;
    out.solver_residual = solver_residual_;
    out.cpu_ms = last_cpu_ms_;
    out.metrics_step = status_step_;
    out.divergence_l2 = metrics_.divergence_l2;
    out.divergence_max = metrics_.divergence_max;
    out.kinetic_energy = metrics_.kinetic_energy;
    out.fluid_cells = metrics_.fluid_cells;
    out.particle_volume = metrics_.particle_volume;
    out.potential_energy = metrics_.potential_energy;
    out.interior_density = metrics_.interior_density;
    out.liquid_volume = metrics_.liquid_volume;
    out.strain = metrics_.strain;
    if (metrics_first_set_ && metrics_first_.liquid_volume > 0.0f)
        out.liquid_volume_drift = float(double(metrics_.liquid_volume) / metrics_first_.liquid_volume - 1.0);
    if (energy_first_set_ && energy_first_ > 0.0)
        out.energy_drift = float((double(metrics_.kinetic_energy) + metrics_.potential_energy) / energy_first_ - 1.0);
    if (metrics_first_set_ && metrics_first_.fluid_cells > 0)
        out.fluid_cell_drift = float(double(metrics_.fluid_cells) / metrics_first_.fluid_cells - 1.0);
    if (metrics_first_set_ && metrics_first_.particle_volume > 0.0f)
        out.particle_volume_drift = float(double(metrics_.particle_volume) / metrics_first_.particle_volume - 1.0);
    const auto& r = runner_->latest_timing();
    out.gpu_step = r.step;
    out.gpu_substeps = r.substeps;
    const auto& list = runner_->stats();
    for (size_t i = 0; i < list.size(); ++i) {
        const int group = list[i].group;
        if (group < 0 || group >= PF_PASS_COUNT) continue;
        out.gpu_ms[group] += r.at(i);
        out.gpu_total_ms += r.at(i);
        out.dispatches[group] += list[i].dispatches;
    }
    out.gpu_total_ms += r.step_ms;
}

void Simulation::set_gpu_timing(pf_gpu_timing timing) {
    runner_->set_timing(timing == PF_GPU_TIMING_OFF    ? gl::TimerRing::Mode::off
                        : timing == PF_GPU_TIMING_STEP ? gl::TimerRing::Mode::step
                                                       : gl::TimerRing::Mode::passes);
    runner_->set_kernel_timing(timing == PF_GPU_TIMING_KERNELS);
}

MeasuredStep Simulation::measured_step() const {
    if (step_time_source_) return step_time_source_();
    const gl::TimerRing::Result& r = runner_->latest_timing();
    MeasuredStep m;
    m.step = r.step;
    m.projections = r.substeps;
    m.total_ms = r.step_ms;
    const auto& stats = runner_->stats();
    for (size_t i = 0; i < stats.size(); ++i) {
        m.total_ms += r.at(i);
        if (stats[i].group == PF_PASS_PRESSURE_SOLVE) m.solve_ms += r.at(i);
    }
    m.iterations = recent_iterations_;
    return m;
}

pf_sim_params Simulation::solve_params() const {
    pf_sim_params p = desc_.params;
    if (iteration_cap_ > 0) p.pressure_iterations = std::min(p.pressure_iterations, iteration_cap_);
    return p;
}

pf_gpu_timing Simulation::gpu_timing() const {
    switch (runner_->timing()) {
        case gl::TimerRing::Mode::off: return PF_GPU_TIMING_OFF;
        case gl::TimerRing::Mode::step: return PF_GPU_TIMING_STEP;
        default: return runner_->kernel_timing() ? PF_GPU_TIMING_KERNELS : PF_GPU_TIMING_PASSES;
    }
}

void Simulation::pass_stats(uint32_t index, pf_pass_stats& out) const {
    gl::StateGuard guard(gl_, gl_state_);
    runner_->poll_timers();
    const PassRunner::Stat& s = runner_->stats()[index];
    out = pf_pass_stats{};
    out.name = s.name.c_str();
    out.group = s.group;
    out.gpu_ms = runner_->gpu_ms(index);
    out.dispatches = s.dispatches;
}

const gl::Buffer& Simulation::grid_buffer(GridBuffer which) const {
    const gl::Buffer* b = &status_;
    switch (which) {
        case GridBuffer::face_accum: b = &face_accum_; break;
        case GridBuffer::face_vel: b = &face_vel_; break;
        case GridBuffer::face_vel_old: b = &face_vel_old_; break;
        case GridBuffer::face_fraction: b = &face_fraction_; break;
        case GridBuffer::face_valid: b = &face_valid_[valid_current_]; break;
        case GridBuffer::cell_count: b = &cell_count_; break;
        case GridBuffer::cell_type: b = &cell_type_; break;
        case GridBuffer::pressure: b = &pressure_; break;
        case GridBuffer::rhs: b = &rhs_; break;
        case GridBuffer::status: b = &status_; break;
    }
    return *b;
}

std::vector<uint32_t> Simulation::read_grid(GridBuffer which) const {
    const gl::Buffer& b = grid_buffer(which);
    std::vector<uint32_t> words(b.bytes() / 4);
    gl::StateGuard guard(gl_, gl_state_);
    b.download(0, b.bytes(), words.data());
    return words;
}

void Simulation::write_grid_for_test(GridBuffer which, const std::vector<uint32_t>& words) {
    const gl::Buffer& b = grid_buffer(which);
    gl::StateGuard guard(gl_, gl_state_);
    b.upload(0, std::min(b.bytes(), words.size() * 4), words.data());
}

std::vector<float> Simulation::read_affine() const {
    if (affine_.bytes() == 0) return {};
    std::vector<float> values(size_t(particle_count_) * 12);
    gl::StateGuard guard(gl_, gl_state_);
    affine_.download(0, values.size() * 4, values.data());
    return values;
}

void Simulation::write_affine_for_test(const std::vector<float>& values) {
    if (affine_.bytes() == 0) return;
    gl::StateGuard guard(gl_, gl_state_);
    affine_.upload(0, std::min(affine_.bytes(), values.size() * 4), values.data());
}

}  // namespace pf
