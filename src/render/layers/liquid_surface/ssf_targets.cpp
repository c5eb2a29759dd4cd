#include "render/layers/liquid_surface/ssf_targets.h"

#include "gl/debug.h"

namespace pf {

namespace {
constexpr const char* kTextureLabels[SsfTargets::texture_count] = {
    "ssf_scene_color",  "ssf_scene_depth",  "ssf_scene_depth_tiles", "ssf_thickness",        "ssf_raw_depth",
    "ssf_depth_buffer", "ssf_smooth_a",     "ssf_smooth_b",          "ssf_shaded_color",     "ssf_shaded_depth",
    "ssf_splat_depth_bits", "ssf_splat_thickness_bits"};
constexpr const char* kFramebufferLabels[SsfTargets::framebuffer_count] = {
    "ssf_thickness_fb", "ssf_depth_fb", "ssf_smooth_a_fb", "ssf_smooth_b_fb", "ssf_shade_fb"};
constexpr GLenum kFormats[SsfTargets::texture_count] = {GL_RGBA16F, GL_R32F,    GL_R32F,    GL_R32F,    GL_R32F,
                                                        GL_DEPTH_COMPONENT32F, GL_R32F, GL_R32F, GL_RGBA16F,
                                                        GL_R32F,    GL_R32UI,   GL_R32UI};
// Bytes per texel of the formats the targets use.
uint64_t texel_bytes(GLenum format) { return format == GL_RGBA16F ? 8 : 4; }
}  // namespace

uint64_t SsfTargets::bytes() const {
    uint64_t total = 0;
    for (int t = 0; t < texture_count; ++t) {
        if (textures_[t].id() == 0) continue;
        const int d = divisor(Texture(t));
        total += uint64_t(reduced(width_, d)) * uint64_t(reduced(height_, d)) * texel_bytes(kFormats[t]);
    }
    return total;
}

SsfTargets::SsfTargets(const gl::Api& gl) : gl_(gl) {
    for (int f = 0; f < framebuffer_count; ++f) {
        framebuffers_[f] = gl::Object(gl_, gl::ObjectKind::framebuffer);
        if (!gl::has_debug_markers(gl_)) continue;
        // A framebuffer name becomes an object (which a label needs) when first bound; the
        // caller's RenderStateGuard restores the binding.
        gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffers_[f].id());
        gl::label_object(gl_, GL_FRAMEBUFFER, framebuffers_[f].id(), kFramebufferLabels[f]);
    }
}

void SsfTargets::allocate(Texture t, GLenum format) {
    textures_[t] = gl::Object(gl_, gl::ObjectKind::texture);
    gl_.BindTexture(GL_TEXTURE_2D, textures_[t].id());
    const int d = divisor(t);
    gl_.TexStorage2D(GL_TEXTURE_2D, 1, format, reduced(width_, d), reduced(height_, d));
    gl::label_object(gl_, GL_TEXTURE, textures_[t].id(), kTextureLabels[t]);
    gl_.BindTexture(GL_TEXTURE_2D, 0);
}

void SsfTargets::attach(Framebuffer f, GLenum attachment, Texture t) {
    gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffers_[f].id());
    gl_.FramebufferTexture2D(GL_DRAW_FRAMEBUFFER, attachment, GL_TEXTURE_2D, textures_[t].id(), 0);
}

void SsfTargets::attach_all() {
    attach(thickness_fb, GL_COLOR_ATTACHMENT0, thickness);
    attach(depth_fb, GL_COLOR_ATTACHMENT0, raw_depth);
    attach(depth_fb, GL_DEPTH_ATTACHMENT, depth_buffer);
    attach(smooth_a_fb, GL_COLOR_ATTACHMENT0, smooth_a);
    attach(smooth_b_fb, GL_COLOR_ATTACHMENT0, smooth_b);
    attach(shade_fb, GL_COLOR_ATTACHMENT0, shaded_color);
    attach(shade_fb, GL_COLOR_ATTACHMENT1, shaded_depth);
    const GLenum two[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    gl_.DrawBuffers(2, two);  // shade_fb is still bound
}

void SsfTargets::ensure(int width, int height, bool scene_depth_copy) {
    const bool resized = width != width_ || height != height_;
    const bool new_depth = scene_depth_copy && textures_[scene_depth].id() == 0;
    if (!resized && !new_depth) return;
    const bool had_depth = textures_[scene_depth].id() != 0;
    width_ = width;
    height_ = height;
    for (int t = 0; t < texture_count; ++t) {
        const bool of_scene_depth = t == scene_depth || t == scene_depth_tiles;
        if (of_scene_depth ? (resized ? had_depth || scene_depth_copy : new_depth) : resized)
            allocate(Texture(t), kFormats[t]);
    }
    attach_all();
}

}  // namespace pf
