#include "gl/render_state_guard.h"

namespace pf::gl {

RenderStateGuard::RenderStateGuard(const Api& gl) : gl_(gl) {
    gl_.GetIntegerv(GL_VERTEX_ARRAY_BINDING, &vao_);
    gl_.GetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw_fbo_);
    gl_.GetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read_fbo_);
    gl_.GetIntegerv(GL_VIEWPORT, viewport_);
    gl_.GetIntegerv(GL_SCISSOR_BOX, scissor_box_);
    for (std::size_t i = 0; i < kCapabilities.size(); ++i) caps_[i] = gl_.IsEnabled(kCapabilities[i]);
    seamless_cube_ = gl_.IsEnabled(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    // Scissor test and blending are per viewport / per draw buffer: glDisable(GL_BLEND) turns
    // off every buffer's, so each is saved to be put back one by one.
    GLint viewports = 1, draw_buffers = 1;
    gl_.GetIntegerv(GL_MAX_VIEWPORTS, &viewports);
    gl_.GetIntegerv(GL_MAX_DRAW_BUFFERS, &draw_buffers);
    scissor_test_.resize(std::size_t(viewports > 0 ? viewports : 1));
    for (std::size_t i = 0; i < scissor_test_.size(); ++i) scissor_test_[i] = gl_.IsEnabledi(GL_SCISSOR_TEST, GLuint(i));
    draw_buffers_.resize(std::size_t(draw_buffers > 0 ? draw_buffers : 1));
    for (std::size_t i = 0; i < draw_buffers_.size(); ++i) {
        DrawBuffer& d = draw_buffers_[i];
        const GLuint b = GLuint(i);
        d.blend = gl_.IsEnabledi(GL_BLEND, b);
        gl_.GetIntegeri_v(GL_BLEND_SRC_RGB, b, &d.src_rgb);
        gl_.GetIntegeri_v(GL_BLEND_DST_RGB, b, &d.dst_rgb);
        gl_.GetIntegeri_v(GL_BLEND_SRC_ALPHA, b, &d.src_alpha);
        gl_.GetIntegeri_v(GL_BLEND_DST_ALPHA, b, &d.dst_alpha);
        gl_.GetIntegeri_v(GL_BLEND_EQUATION_RGB, b, &d.eq_rgb);
        gl_.GetIntegeri_v(GL_BLEND_EQUATION_ALPHA, b, &d.eq_alpha);
        gl_.GetBooleani_v(GL_COLOR_WRITEMASK, b, d.mask);
    }
    gl_.GetIntegerv(GL_DEPTH_FUNC, &depth_func_);
    gl_.GetBooleanv(GL_DEPTH_WRITEMASK, &depth_mask_);
    gl_.GetDoublev(GL_DEPTH_RANGE, depth_range_);
    // Core profiles keep one polygon mode for both faces; some drivers report it twice.
    gl_.GetIntegerv(GL_POLYGON_MODE, polygon_mode_);
    gl_.GetIntegerv(GL_ACTIVE_TEXTURE, &active_texture_);
    for (GLuint u = 0; u < PF_RENDER_TEX_UNITS; ++u) {
        gl_.ActiveTexture(GL_TEXTURE0 + u);
        gl_.GetIntegerv(GL_TEXTURE_BINDING_2D, &units_[u].tex_2d);
        gl_.GetIntegerv(GL_TEXTURE_BINDING_CUBE_MAP, &units_[u].tex_cube);
        gl_.GetIntegerv(GL_SAMPLER_BINDING, &units_[u].sampler);
    }
    gl_.ActiveTexture(GLenum(active_texture_));
    for (GLuint i = 0; i < PF_RENDER_IMAGE_UNITS; ++i) {
        ImageUnit& m = images_[i];
        gl_.GetIntegeri_v(GL_IMAGE_BINDING_NAME, i, &m.name);
        gl_.GetIntegeri_v(GL_IMAGE_BINDING_LEVEL, i, &m.level);
        gl_.GetIntegeri_v(GL_IMAGE_BINDING_LAYERED, i, &m.layered);
        gl_.GetIntegeri_v(GL_IMAGE_BINDING_LAYER, i, &m.layer);
        gl_.GetIntegeri_v(GL_IMAGE_BINDING_ACCESS, i, &m.access);
        gl_.GetIntegeri_v(GL_IMAGE_BINDING_FORMAT, i, &m.format);
    }
    gl_.GetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, PF_UBO_RENDER, &ubo_);
    gl_.GetInteger64i_v(GL_UNIFORM_BUFFER_START, PF_UBO_RENDER, &ubo_start_);
    gl_.GetInteger64i_v(GL_UNIFORM_BUFFER_SIZE, PF_UBO_RENDER, &ubo_size_);
}

RenderStateGuard::~RenderStateGuard() {
    gl_.BindVertexArray(GLuint(vao_));
    gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(draw_fbo_));
    gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(read_fbo_));
    gl_.Viewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    gl_.Scissor(scissor_box_[0], scissor_box_[1], scissor_box_[2], scissor_box_[3]);
    for (std::size_t i = 0; i < kCapabilities.size(); ++i) {
        if (caps_[i]) {
            gl_.Enable(kCapabilities[i]);
        } else {
            gl_.Disable(kCapabilities[i]);
        }
    }
    if (seamless_cube_) {
        gl_.Enable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    } else {
        gl_.Disable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    }
    for (std::size_t i = 0; i < scissor_test_.size(); ++i) {
        if (scissor_test_[i]) {
            gl_.Enablei(GL_SCISSOR_TEST, GLuint(i));
        } else {
            gl_.Disablei(GL_SCISSOR_TEST, GLuint(i));
        }
    }
    for (std::size_t i = 0; i < draw_buffers_.size(); ++i) {
        const DrawBuffer& d = draw_buffers_[i];
        const GLuint b = GLuint(i);
        if (d.blend) {
            gl_.Enablei(GL_BLEND, b);
        } else {
            gl_.Disablei(GL_BLEND, b);
        }
        gl_.BlendFuncSeparatei(b, GLenum(d.src_rgb), GLenum(d.dst_rgb), GLenum(d.src_alpha), GLenum(d.dst_alpha));
        gl_.BlendEquationSeparatei(b, GLenum(d.eq_rgb), GLenum(d.eq_alpha));
        gl_.ColorMaski(b, d.mask[0], d.mask[1], d.mask[2], d.mask[3]);
    }
    gl_.DepthFunc(GLenum(depth_func_));
    gl_.DepthMask(depth_mask_);
    gl_.DepthRange(depth_range_[0], depth_range_[1]);
    gl_.PolygonMode(GL_FRONT_AND_BACK, GLenum(polygon_mode_[0]));
    for (GLuint u = 0; u < PF_RENDER_TEX_UNITS; ++u) {
        gl_.ActiveTexture(GL_TEXTURE0 + u);
        gl_.BindTexture(GL_TEXTURE_2D, GLuint(units_[u].tex_2d));
        gl_.BindTexture(GL_TEXTURE_CUBE_MAP, GLuint(units_[u].tex_cube));
        gl_.BindSampler(u, GLuint(units_[u].sampler));
    }
    gl_.ActiveTexture(GLenum(active_texture_));
    for (GLuint i = 0; i < PF_RENDER_IMAGE_UNITS; ++i) {
        const ImageUnit& m = images_[i];
        gl_.BindImageTexture(i, GLuint(m.name), m.level, GLboolean(m.layered), m.layer, GLenum(m.access),
                             GLenum(m.format));
    }
    if (ubo_ != 0 && ubo_size_ > 0) {
        gl_.BindBufferRange(GL_UNIFORM_BUFFER, PF_UBO_RENDER, GLuint(ubo_), GLintptr(ubo_start_),
                            GLsizeiptr(ubo_size_));
    } else {
        gl_.BindBufferBase(GL_UNIFORM_BUFFER, PF_UBO_RENDER, GLuint(ubo_));
    }
}

}  // namespace pf::gl
