// The two checks around GPU allocations, logged with the caller's context: a buffer larger than
// the GL's largest storage block is refused before it is made (PF_ERROR_CAPACITY), and a GL error
// after allocating is reported as PF_ERROR_OUT_OF_MEMORY (GL_OUT_OF_MEMORY) or PF_ERROR_GL.
#pragma once
#include <cstdint>
#include <string>

#include "api/log.h"
#include "gl/gl.h"
#include "pf/pf.h"

namespace pf::gl {

// PF_OK when `bytes` fits GL_MAX_SHADER_STORAGE_BLOCK_SIZE; else logs "<needs> a buffer of N bytes
// <per>, more than this GL's GL_MAX_SHADER_STORAGE_BLOCK_SIZE (M); <advice>". `needs` names who
// ("pf_set_params: APIC needs"), `per` what the size follows ("(48 per particle)").
inline pf_result check_storage_block(const Api& gl, const Log& log, uint64_t bytes, const std::string& needs,
                                     const std::string& per, const char* advice) {
    GLint64 max_block = 0;
    gl.GetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &max_block);
    if (bytes <= uint64_t(max_block)) return PF_OK;
    return log.error(PF_ERROR_CAPACITY, needs + " a buffer of " + std::to_string(bytes) + " bytes " + per +
                                            ", more than this GL's GL_MAX_SHADER_STORAGE_BLOCK_SIZE (" +
                                            std::to_string(max_block) + "); " + advice);
}

// PF_OK when the GL reports no error; else logs "<what> failed (GL error 0x...)".
inline pf_result check_allocated(const Api& gl, const Log& log, const std::string& what) {
    const GLenum err = gl.GetError();
    if (err == GL_NO_ERROR) return PF_OK;
    return log.error(err == GL_OUT_OF_MEMORY ? PF_ERROR_OUT_OF_MEMORY : PF_ERROR_GL,
                     what + " failed (GL error " + hex(err) + ")");
}

}  // namespace pf::gl
