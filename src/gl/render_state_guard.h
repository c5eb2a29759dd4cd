// Saves the raster-side GL state the render calls touch and restores it on scope exit (the
// compute-side bindings are gl::StateGuard's job; render calls hold both). Covers: VAO, draw
// and read framebuffers, viewport and scissor box, every capability a draw depends on
// (blend per draw buffer, depth/stencil/scissor tests, culling, multisample and coverage
// switches, sRGB, depth clamp, rasterizer discard, polygon offset, logic op, dither, seamless
// cube maps), blend functions and equations and colour masks per draw buffer, depth function,
// mask and range, polygon mode, the active texture unit and the texture/sampler bindings of
// the render texture units, the render image units and the render uniform block binding.
#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include "common/render_slots.h"
#include "gl/gl.h"

namespace pf::gl {

class RenderStateGuard {
public:
    explicit RenderStateGuard(const Api& gl);
    ~RenderStateGuard();
    RenderStateGuard(const RenderStateGuard&) = delete;
    RenderStateGuard& operator=(const RenderStateGuard&) = delete;

    // Capabilities saved and restored (glIsEnabled / glEnable / glDisable).
    static constexpr std::array<GLenum, 17> kCapabilities = {
        GL_DEPTH_TEST,         GL_CULL_FACE,          GL_STENCIL_TEST,
        GL_MULTISAMPLE,        GL_FRAMEBUFFER_SRGB,   GL_DEPTH_CLAMP,
        GL_RASTERIZER_DISCARD, GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE,
        GL_POLYGON_OFFSET_POINT, GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_ALPHA_TO_ONE,
        GL_SAMPLE_COVERAGE,    GL_SAMPLE_MASK,        GL_SAMPLE_SHADING,
        GL_COLOR_LOGIC_OP,     GL_DITHER};

private:
    struct DrawBuffer {  // per draw buffer: blend switch, functions, equations, colour mask
        GLboolean blend = GL_FALSE;
        GLint src_rgb = GL_ONE, dst_rgb = GL_ZERO, src_alpha = GL_ONE, dst_alpha = GL_ZERO;
        GLint eq_rgb = GL_FUNC_ADD, eq_alpha = GL_FUNC_ADD;
        GLboolean mask[4] = {GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE};
    };
    struct TextureUnit {
        GLint tex_2d = 0, tex_cube = 0, sampler = 0;
    };
    struct ImageUnit {
        GLint name = 0, level = 0, layered = 0, layer = 0, access = GL_READ_ONLY, format = GL_R32F;
    };

    const Api& gl_;
    GLint vao_ = 0, draw_fbo_ = 0, read_fbo_ = 0;
    GLint viewport_[4] = {}, scissor_box_[4] = {};
    std::array<GLboolean, kCapabilities.size()> caps_{};
    GLboolean seamless_cube_ = GL_FALSE;
    std::vector<GLboolean> scissor_test_;  // per viewport index
    std::vector<DrawBuffer> draw_buffers_;
    GLint depth_func_ = GL_LESS;
    GLboolean depth_mask_ = GL_TRUE;
    GLdouble depth_range_[2] = {0.0, 1.0};
    GLint polygon_mode_[2] = {GL_FILL, GL_FILL};
    GLint active_texture_ = GL_TEXTURE0;
    std::array<TextureUnit, PF_RENDER_TEX_UNITS> units_{};
    std::array<ImageUnit, PF_RENDER_IMAGE_UNITS> images_{};
    GLint ubo_ = 0;
    GLint64 ubo_start_ = 0, ubo_size_ = 0;
};

}  // namespace pf::gl
