#include "render/target_check.h"

#include <cstdio>
#include <string>

#include "common/render_slots.h"

namespace pf {

namespace {
using gl::hex;

struct Check {
    const gl::Api& gl;
    const Log& log;
    const char* fn;

    pf_result bad(const std::string& what) const {
        return log.error(PF_ERROR_INVALID_ARGUMENT, std::string(fn) + ": " + what);
    }

    // Binding a texture to a target it was not created for is GL_INVALID_OPERATION: the one
    // GL 4.3 way to learn a texture's target (glGetTextureParameteriv(GL_TEXTURE_TARGET) is 4.5).
    bool binds_as(GLuint unit, GLenum target, GLuint name) const {
        gl.ActiveTexture(GL_TEXTURE0 + unit);
        gl.BindTexture(target, name);
        const bool ok = gl.GetError() == GL_NO_ERROR;
        gl.BindTexture(target, 0);
        return ok;
    }

    GLint level0(GLenum target, GLenum pname) const {
        GLint v = 0;
        gl.GetTexLevelParameteriv(target, 0, pname, &v);
        return v;
    }

    // A 2D texture on `unit` covering the viewport; `depth` selects a depth or a colour format.
    pf_result texture_2d(const char* field, GLuint name, GLuint unit, bool depth, const pf_camera& cam,
                         GLenum& format) const {
        const std::string f = std::string("target->") + field + " (" + std::to_string(name) + ")";
        if (!gl.IsTexture(name)) return bad(f + " is not a texture");
        if (!binds_as(unit, GL_TEXTURE_2D, name))
            return bad(f + " is not a GL_TEXTURE_2D (multisampled, array or cube textures are not accepted)");
        gl.BindTexture(GL_TEXTURE_2D, name);
        const GLint w = level0(GL_TEXTURE_2D, GL_TEXTURE_WIDTH), h = level0(GL_TEXTURE_2D, GL_TEXTURE_HEIGHT);
        const GLint depth_bits = level0(GL_TEXTURE_2D, GL_TEXTURE_DEPTH_SIZE);
        const GLint red_type = level0(GL_TEXTURE_2D, GL_TEXTURE_RED_TYPE);
        format = GLenum(level0(GL_TEXTURE_2D, GL_TEXTURE_INTERNAL_FORMAT));
        // The scene copy fetches level 0 of what a shader samples: the depth, not the stencil.
        GLint base_level = 0, stencil_mode = GL_DEPTH_COMPONENT;
        gl.GetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, &base_level);
        if (depth) gl.GetTexParameteriv(GL_TEXTURE_2D, GL_DEPTH_STENCIL_TEXTURE_MODE, &stencil_mode);
        gl.BindTexture(GL_TEXTURE_2D, 0);
        if (w <= 0 || h <= 0) return bad(f + " has no level-0 image");
        if (base_level != 0) return bad(f + " has GL_TEXTURE_BASE_LEVEL " + std::to_string(base_level) + " (0 is read)");
        if (stencil_mode != GL_DEPTH_COMPONENT)
            return bad(f + " samples its stencil (GL_DEPTH_STENCIL_TEXTURE_MODE); the depth is read");
        if (depth && depth_bits <= 0) return bad(f + " is not a depth texture (internal format " + hex(format) + ")");
        if (!depth && depth_bits > 0) return bad(f + " is a depth texture; the scene colour must be a colour texture");
        if (!depth && (red_type == GL_INT || red_type == GL_UNSIGNED_INT))
            return bad(f + " has an integer format (" + hex(format) + "); it cannot be sampled as colour");
        const int64_t x1 = int64_t(cam.viewport[0]) + cam.viewport[2], y1 = int64_t(cam.viewport[1]) + cam.viewport[3];
        if (x1 > w || y1 > h) {
            return bad(f + " is " + std::to_string(w) + "x" + std::to_string(h) + ", smaller than camera->viewport (ends at " +
                       std::to_string(x1) + ", " + std::to_string(y1) + ")");
        }
        return PF_OK;
    }
};
}  // namespace

pf_result check_render_target(const gl::Api& gl, const Log& log, const char* fn, const pf_render_target& target,
                              const pf_camera& camera, bool ssf) {
    const Check c{gl, log, fn};
    const std::string fb = "target->framebuffer (" + std::to_string(target.framebuffer) + ")";
    if (target.framebuffer != 0 && !gl.IsFramebuffer(target.framebuffer)) return c.bad(fb + " is not a framebuffer object");
    gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, target.framebuffer);
    const GLenum status = gl.CheckFramebufferStatus(GL_DRAW_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) return c.bad(fb + " is not complete (status " + hex(status) + ")");
    if (!ssf) return PF_OK;

    if (target.scene_color == 0) return c.bad("target->scene_color is required (the scene behind the liquid)");
    GLenum color_format = 0;
    if (pf_result r = c.texture_2d("scene_color", target.scene_color, PF_TEX_SCENE_COLOR, false, camera, color_format);
        r != PF_OK)
        return r;
    if (target.scene_depth != 0) {
        GLenum depth_format = 0;
        if (pf_result r = c.texture_2d("scene_depth", target.scene_depth, PF_TEX_SCENE_DEPTH, true, camera, depth_format);
            r != PF_OK)
            return r;
    }
    if (target.environment_cubemap != 0) {
        const std::string f = "target->environment_cubemap (" + std::to_string(target.environment_cubemap) + ")";
        if (!gl.IsTexture(target.environment_cubemap)) return c.bad(f + " is not a texture");
        if (!c.binds_as(PF_TEX_ENVIRONMENT, GL_TEXTURE_CUBE_MAP, target.environment_cubemap))
            return c.bad(f + " is not a GL_TEXTURE_CUBE_MAP");
        gl.BindTexture(GL_TEXTURE_CUBE_MAP, target.environment_cubemap);
        const GLint w = c.level0(GL_TEXTURE_CUBE_MAP_POSITIVE_X, GL_TEXTURE_WIDTH);
        gl.BindTexture(GL_TEXTURE_CUBE_MAP, 0);
        if (w <= 0) return c.bad(f + " has no level-0 image");
    }
    return PF_OK;
}

}  // namespace pf
