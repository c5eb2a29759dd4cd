// Checks that the GL objects an engine names in pf_render_target are what pf.h says they are,
// before anything is drawn: framebuffer complete, scene colour a single-sampled non-integer
// GL_TEXTURE_2D covering the viewport, scene depth a depth GL_TEXTURE_2D covering it,
// environment a GL_TEXTURE_CUBE_MAP. Binds on the render texture units and the draw
// framebuffer: call under a RenderStateGuard.
#pragma once
#include "api/log.h"
#include "gl/gl.h"
#include "pf/pf.h"

namespace pf {

// `ssf`: pf_render_ssf (checks the scene textures) rather than pf_render_particles (only the
// framebuffer). `fn` prefixes messages. PF_OK or PF_ERROR_INVALID_ARGUMENT naming the field.
pf_result check_render_target(const gl::Api& gl, const Log& log, const char* fn, const pf_render_target& target,
                              const pf_camera& camera, bool ssf);

}  // namespace pf
