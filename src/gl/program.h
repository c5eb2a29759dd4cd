// Compute programs built from the embedded sources, compiled on first use and cached per
// simulation (programs are per-context objects; nothing is shared globally).
#pragma once
#include <array>
#include <cstdint>
#include <string>

#include "gl/gl.h"
#include "gl/shader_source.h"

namespace pf::gl {

// Compiles and links one compute shader from complete source text. On failure returns 0
// and fills `error` with the annotated compile/link log.
GLuint build_compute_program(const Api& gl, const ExpandedSource& src, const std::string& name,
                             std::string& error);

class ProgramCache {
public:
    explicit ProgramCache(const Api& gl) : gl_(gl) {}
    ~ProgramCache();
    ProgramCache(const ProgramCache&) = delete;
    ProgramCache& operator=(const ProgramCache&) = delete;

    // The program for `id`, building it if needed; 0 with `error` set on failure.
    GLuint get(ProgramId id, std::string& error);
    // The program if it was built already, else 0.
    GLuint built(ProgramId id) const { return programs_[static_cast<size_t>(id)]; }

private:
    const Api& gl_;
    std::array<GLuint, static_cast<size_t>(ProgramId::count)> programs_{};
};

}  // namespace pf::gl
