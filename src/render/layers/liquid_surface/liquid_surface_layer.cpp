#include "render/layers/liquid_surface/liquid_surface_layer.h"

#include <string>
#include <utility>

#include <glm/gtc/type_ptr.hpp>

#include "common/render_slots.h"
#include "gl/allocation_check.h"
#include "render/render_context.h"
#include "sim/simulation.h"

namespace pf {

static_assert(PF_SSF_FILTER_BILATERAL == PF_SSF_FILTER_BILATERAL_ID, "filter ids shared with GLSL");
static_assert(PF_SSF_FILTER_NARROW_RANGE == PF_SSF_FILTER_NARROW_RANGE_ID, "filter ids shared with GLSL");

using gl::ProgramId;

namespace {
// Diameter on screen (pixels) of a sphere from which the compute splat sums thickness per
// workgroup (ssf_splat.comp, PF_SPLAT_SHARED; docs/notes/2026-11-27-render-cost-steps.md). Measured on
// the H100: spheres 5.0 px across gained (dam_break_1m at 720p), 3.7 px lost (dam_break_10m at 1080p).
constexpr double kSharedThicknessDiameter = 4.5;

// Diameter in pixels of a liquid sphere at the simulation grid's centre.
double sphere_diameter_px(const RenderFrame& f, const glm::mat4& domain_to_world) {
    const pf_camera& cam = *f.camera;
    const double diameter = 2.0 * double(f.ssf->particle_radius) * double(camera_pixels_per_metre(cam));
    if (camera_orthographic(cam)) return diameter;
    glm::vec4 centre(1.0f);
    for (int a = 0; a < 3; ++a) centre[a] = f.cells.origin[a] + 0.5f * f.cells.cell_size * float(f.cells.dims[a]);
    const glm::vec4 eye = glm::make_mat4(cam.view) * domain_to_world * centre;
    const double depth = -double(eye.z);
    return depth > double(f.ssf->particle_radius) ? diameter / depth : 1e30;
}
}  // namespace

pf_result LiquidSurfaceLayer::prepare(RenderContext& c, const RenderFrame& f) {
    const pf_ssf_params& params = *f.ssf;
    const bool compute = params.path == PF_SSF_PATH_COMPUTE;
    const bool narrow = params.filter == PF_SSF_FILTER_NARROW_RANGE;
    // Raster path: sphere sprites for THICKNESS and DEPTH. Compute path: the splat clear, one
    // splat of both and its resolve.
    thickness_ = depth_ = splat_clear_ = splat_ = splat_resolve_ = smooth_ = 0;
    // The tiled resolve's vertex shader reads the tile list, a storage buffer.
    tiled_resolve_ = compute && c.vertex_storage_buffers();
    for (auto [id, out] : {std::pair{ProgramId::ssf_scene_copy, &scene_copy_},
                           std::pair{compute ? ProgramId::ssf_shade_cs : ProgramId::ssf_shade_fs, &shade_},
                           std::pair{tiled_resolve_ ? ProgramId::ssf_resolve_tiles : ProgramId::ssf_resolve, &resolve_}}) {
        if (pf_result r = c.program(id, f.fn, *out); r != PF_OK) return r;
    }
    const bool shared = compute && sphere_diameter_px(f, c.sim().domain_to_world()) >= kSharedThicknessDiameter;
    const std::vector<std::pair<ProgramId, GLuint*>> splatting =
        compute ? std::vector<std::pair<ProgramId, GLuint*>>{{ProgramId::ssf_splat_clear_cs, &splat_clear_},
                                                             {shared ? ProgramId::ssf_splat_shared_cs
                                                                     : ProgramId::ssf_splat_cs,
                                                              &splat_},
                                                             {ProgramId::ssf_splat_resolve_cs, &splat_resolve_}}
                : std::vector<std::pair<ProgramId, GLuint*>>{{ProgramId::ssf_thickness, &thickness_},
                                                             {ProgramId::ssf_depth, &depth_}};
    for (auto [id, out] : splatting) {
        if (pf_result r = c.program(id, f.fn, *out); r != PF_OK) return r;
    }
    if (params.filter != PF_SSF_FILTER_NONE) {
        const ProgramId id = compute ? (narrow ? ProgramId::ssf_smooth_narrow_cs : ProgramId::ssf_smooth_bilateral_cs)
                                     : (narrow ? ProgramId::ssf_smooth_narrow_fs : ProgramId::ssf_smooth_bilateral_fs);
        if (pf_result r = c.program(id, f.fn, smooth_); r != PF_OK) return r;
    }
    const gl::Api& gl = c.gl();
    const int w = f.width(), h = f.height();
    if (!targets_) targets_ = std::make_unique<SsfTargets>(gl);
    gl.ActiveTexture(GL_TEXTURE0 + PF_TEX_SCENE_COLOR);  // ensure() binds on the active unit
    targets_->ensure(w, h, f.target->scene_depth != 0);
    if (compute) {
        const size_t tiles = size_t(SsfTargets::reduced(w, PF_RENDER_TILE)) * size_t(SsfTargets::reduced(h, PF_RENDER_TILE));
        const size_t bytes = (PF_TILES_HEADER + tiles) * sizeof(uint32_t);
        if (liquid_tiles_.bytes() < bytes) liquid_tiles_ = gl::Buffer(gl, bytes, GL_DYNAMIC_COPY, "ssf_liquid_tiles");
    }
    return gl::check_allocated(gl, c.log(),
                               std::string(f.fn) + ": allocating " + std::to_string(w) + "x" + std::to_string(h) +
                                   " render targets");
}

void LiquidSurfaceLayer::fill(const RenderFrame& f, RenderUniforms& u) const {
    fill_ssf(*f.ssf, f.target->scene_depth != 0, f.target->environment_cubemap != 0, f.particle_volume, u);
    fill_spray(f.ssf->spray_radius_scale, f.cells.origin, f.cells.cell_size, f.cells.dims, f.cells.rest_count,
               f.cells.current, u);
}

std::vector<RenderPass> LiquidSurfaceLayer::passes(const RenderFrame& f) {
    const bool compute = f.ssf->path == PF_SSF_PATH_COMPUTE;
    auto pass = [this](pf_render_pass timer, void (LiquidSurfaceLayer::*run)(RenderContext&, const RenderFrame&)) {
        return RenderPass{timer, [this, run](RenderContext& c, const RenderFrame& f) { (this->*run)(c, f); }};
    };
    return {pass(PF_RENDER_PASS_SCENE_COPY, &LiquidSurfaceLayer::scene_copy),
            pass(PF_RENDER_PASS_THICKNESS, compute ? &LiquidSurfaceLayer::splat : &LiquidSurfaceLayer::thickness),
            pass(PF_RENDER_PASS_DEPTH, compute ? &LiquidSurfaceLayer::splat_resolve : &LiquidSurfaceLayer::depth),
            pass(PF_RENDER_PASS_SMOOTH, &LiquidSurfaceLayer::smooth),
            pass(PF_RENDER_PASS_SHADE, &LiquidSurfaceLayer::shade),
            pass(PF_RENDER_PASS_RESOLVE, &LiquidSurfaceLayer::resolve)};
}

// A compute copy (ssf_scene_copy.comp) rather than a blit: it needs no framebuffer around the
// engine's textures (nothing to attach, complete or detach), and on the H100 a 1080p blit of
// colour and depth took 0.52 ms (docs/notes/2026-11-26-render-cost-steps.md).
void LiquidSurfaceLayer::scene_copy(RenderContext& c, const RenderFrame& f) {
    const gl::Api& gl = c.gl();
    c.bind_texture(PF_TEX_SCENE_COLOR, GL_TEXTURE_2D, f.target->scene_color, false);
    c.bind_texture(PF_TEX_SCENE_DEPTH, GL_TEXTURE_2D, f.target->scene_depth, false);
    gl.BindImageTexture(PF_IMG_SCENE_COLOR, targets_->texture(SsfTargets::scene_color), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                        GL_RGBA16F);
    if (f.target->scene_depth != 0) {
        gl.BindImageTexture(PF_IMG_SCENE_DEPTH, targets_->texture(SsfTargets::scene_depth), 0, GL_FALSE, 0,
                            GL_WRITE_ONLY, GL_R32F);
        gl.BindImageTexture(PF_IMG_SCENE_DEPTH_TILES, targets_->texture(SsfTargets::scene_depth_tiles), 0, GL_FALSE,
                            0, GL_WRITE_ONLY, GL_R32F);
    }
    gl.UseProgram(scene_copy_);
    c.dispatch_screen(f.width(), f.height());
    // The engine's textures stay bound only for this pass.
    c.bind_texture(PF_TEX_SCENE_COLOR, GL_TEXTURE_2D, 0, false);
    c.bind_texture(PF_TEX_SCENE_DEPTH, GL_TEXTURE_2D, 0, false);
    c.handoff().scene_eye_depth = f.target->scene_depth != 0 ? targets_->texture(SsfTargets::scene_depth) : 0;
}

void LiquidSurfaceLayer::thickness(RenderContext& c, const RenderFrame& f) {
    const gl::Api& gl = c.gl();
    gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, targets_->framebuffer(SsfTargets::thickness_fb));
    gl.Viewport(0, 0, SsfTargets::half(f.width()), SsfTargets::half(f.height()));
    const GLfloat zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    gl.ClearBufferfv(GL_COLOR, 0, zero);
    gl.Enable(GL_BLEND);
    gl.BlendEquation(GL_FUNC_ADD);
    gl.BlendFunc(GL_ONE, GL_ONE);
    c.bind_texture(PF_TEX_SCENE_DEPTH, GL_TEXTURE_2D, targets_->texture(SsfTargets::scene_depth), false);
    gl.UseProgram(thickness_);
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, PF_SSBO_CELL_COUNT, f.cells.counts);  // spray's radius
    c.draw_spheres();
    gl.Disable(GL_BLEND);
}

void LiquidSurfaceLayer::depth(RenderContext& c, const RenderFrame& f) {
    const gl::Api& gl = c.gl();
    gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, targets_->framebuffer(SsfTargets::depth_fb));
    gl.Viewport(0, 0, f.width(), f.height());
    const GLfloat no_liquid[4] = {float(PF_NO_LIQUID), 0.0f, 0.0f, 0.0f}, far_depth = 1.0f;
    gl.ClearBufferfv(GL_COLOR, 0, no_liquid);
    gl.ClearBufferfv(GL_DEPTH, 0, &far_depth);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_LESS);
    gl.UseProgram(depth_);
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, PF_SSBO_CELL_COUNT, f.cells.counts);  // spray's radius
    c.draw_spheres();
    gl.Disable(GL_DEPTH_TEST);
}

void LiquidSurfaceLayer::splat(RenderContext& c, const RenderFrame& f) {
    const gl::Api& gl = c.gl();
    const GLuint depth_bits = targets_->texture(SsfTargets::splat_depth_bits);
    const GLuint thickness_bits = targets_->texture(SsfTargets::splat_thickness_bits);
    gl.BindImageTexture(PF_IMG_SPLAT_DEPTH, depth_bits, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
    gl.BindImageTexture(PF_IMG_SPLAT_THICKNESS, thickness_bits, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, PF_SSBO_LIQUID_TILES, liquid_tiles_.id());
    gl.UseProgram(splat_clear_);
    c.dispatch_screen(f.width(), f.height());
    gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);  // the emptied tile list, before the splat resolve appends
    pf_gl_buffers b{};
    c.sim().gl_buffers(b);
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, PF_SSBO_PARTICLE_POS, b.positions);
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, PF_SSBO_PARTICLE_COUNT, b.draw_indirect);
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, PF_SSBO_CELL_COUNT, f.cells.counts);
    // Walked in the simulation's tile order where it has one: neighbouring invocations splat
    // neighbouring spheres (docs/rendering.md).
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, PF_SSBO_PARTICLE_ORDER, f.cells.order ? f.cells.order : b.positions);
    gl.ProgramUniform1ui(splat_, PF_LOC_SPLAT_ORDERED, f.cells.order ? 1u : 0u);
    c.bind_texture(PF_TEX_SCENE_DEPTH, GL_TEXTURE_2D, targets_->texture(SsfTargets::scene_depth), false);
    c.bind_texture(PF_TEX_SCENE_DEPTH_TILES, GL_TEXTURE_2D, targets_->texture(SsfTargets::scene_depth_tiles), false);
    c.dispatch_particles(splat_);
}

void LiquidSurfaceLayer::splat_resolve(RenderContext& c, const RenderFrame& f) {
    const gl::Api& gl = c.gl();
    gl.BindImageTexture(PF_IMG_RAW_DEPTH, targets_->texture(SsfTargets::raw_depth), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                        GL_R32F);
    gl.BindImageTexture(PF_IMG_THICKNESS, targets_->texture(SsfTargets::thickness), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                        GL_R32F);
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, PF_SSBO_LIQUID_TILES, liquid_tiles_.id());
    gl.UseProgram(splat_resolve_);
    c.dispatch_screen(f.width(), f.height());
    // The tile list is SHADE's dispatch record and RESOLVE's draw record and vertex input.
    gl.MemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
}

// Alternating horizontal and vertical 1D passes, filter_iterations times, ping-ponging
// between smooth_a and smooth_b; surface_ is the texture holding the surface to shade.
void LiquidSurfaceLayer::smooth(RenderContext& c, const RenderFrame& f) {
    const pf_ssf_params& params = *f.ssf;
    surface_ = SsfTargets::raw_depth;
    if (params.filter == PF_SSF_FILTER_NONE) return;
    const gl::Api& gl = c.gl();
    const bool compute = params.path == PF_SSF_PATH_COMPUTE;
    gl.UseProgram(smooth_);
    if (!compute) gl.Viewport(0, 0, f.width(), f.height());
    for (uint32_t pass = 0; pass < 2 * params.filter_iterations; ++pass) {
        const SsfTargets::Texture dst = (pass % 2 == 0) ? SsfTargets::smooth_a : SsfTargets::smooth_b;
        gl.ProgramUniform2i(smooth_, PF_LOC_SMOOTH_DIRECTION, pass % 2 == 0 ? 1 : 0, pass % 2 == 0 ? 0 : 1);
        c.bind_texture(PF_TEX_LIQUID_DEPTH, GL_TEXTURE_2D, targets_->texture(surface_), false);
        if (compute) {
            gl.BindImageTexture(PF_IMG_SMOOTH_OUT, targets_->texture(dst), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
            c.dispatch_screen(f.width(), f.height());
        } else {
            gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER,
                               targets_->framebuffer(dst == SsfTargets::smooth_a ? SsfTargets::smooth_a_fb
                                                                                 : SsfTargets::smooth_b_fb));
            c.draw_fullscreen();
        }
        surface_ = dst;
    }
}

void LiquidSurfaceLayer::shade(RenderContext& c, const RenderFrame& f) {
    const gl::Api& gl = c.gl();
    c.bind_texture(PF_TEX_SCENE_COLOR, GL_TEXTURE_2D, targets_->texture(SsfTargets::scene_color), true);
    c.bind_texture(PF_TEX_LIQUID_DEPTH, GL_TEXTURE_2D, targets_->texture(surface_), false);
    c.bind_texture(PF_TEX_THICKNESS, GL_TEXTURE_2D, targets_->texture(SsfTargets::thickness), true);
    c.handoff().liquid_eye_depth = targets_->texture(surface_);
    c.bind_texture(PF_TEX_ENVIRONMENT, GL_TEXTURE_CUBE_MAP, f.target->environment_cubemap, true);
    gl.UseProgram(shade_);
    if (f.ssf->path == PF_SSF_PATH_COMPUTE) {
        gl.BindImageTexture(PF_IMG_SHADE_COLOR, targets_->texture(SsfTargets::shaded_color), 0, GL_FALSE, 0,
                            GL_WRITE_ONLY, GL_RGBA16F);
        gl.BindImageTexture(PF_IMG_SHADE_DEPTH, targets_->texture(SsfTargets::shaded_depth), 0, GL_FALSE, 0,
                            GL_WRITE_ONLY, GL_R32F);
        // Only the tiles holding liquid (the splat resolve's list): the resolve reads no others.
        gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, PF_SSBO_LIQUID_TILES, liquid_tiles_.id());
        gl.BindBuffer(GL_DISPATCH_INDIRECT_BUFFER, liquid_tiles_.id());
        gl.DispatchComputeIndirect(GLintptr(PF_TILES_DISPATCH * sizeof(uint32_t)));
        gl.MemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    } else {
        gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, targets_->framebuffer(SsfTargets::shade_fb));
        gl.Viewport(0, 0, f.width(), f.height());
        c.draw_fullscreen();
    }
}

void LiquidSurfaceLayer::resolve(RenderContext& c, const RenderFrame& f) {
    const gl::Api& gl = c.gl();
    const int32_t* v = f.camera->viewport;
    gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, f.target->framebuffer);
    gl.Viewport(v[0], v[1], v[2], v[3]);
    // ALWAYS with writes on: the liquid already passed the scene-depth test; this only stores
    // its depth (a target without depth attachment simply has none to write).
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_ALWAYS);
    gl.Enable(GL_FRAMEBUFFER_SRGB);  // encode into an sRGB target, matching the decoded copy
    c.bind_texture(PF_TEX_SHADED_COLOR, GL_TEXTURE_2D, targets_->texture(SsfTargets::shaded_color), false);
    c.bind_texture(PF_TEX_SHADED_DEPTH, GL_TEXTURE_2D, targets_->texture(SsfTargets::shaded_depth), false);
    gl.UseProgram(resolve_);
    if (tiled_resolve_) {
        // Only the tiles the splat resolve found liquid in: on the H100 a full-screen 1080p
        // resolve was 0.13 ms of fragment work, mostly discarded (docs/notes/2026-11-27-render-cost-steps.md).
        gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, PF_SSBO_LIQUID_TILES, liquid_tiles_.id());
        c.draw_indirect_without_attributes(liquid_tiles_.id());
    } else {
        c.draw_fullscreen();
    }
}

}  // namespace pf
