// Programs built from the embedded sources (compute, or vertex + fragment), compiled on first
// use and cached per owner (programs are per-context objects; nothing is shared globally).
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/shader_source.h"

namespace pf::gl {

// One stage of a program: its GL shader type and complete source text.
struct ShaderStage {
    GLenum type;
    ExpandedSource source;
};

// Compiles every stage and links them into one program. On failure returns 0 and fills
// `error` with the annotated compile/link log. `retrievable`: the program's binary will be
// read back (GL_PROGRAM_BINARY_RETRIEVABLE_HINT, set before linking).
GLuint build_program(const Api& gl, const std::vector<ShaderStage>& stages, const std::string& name,
                     std::string& error, bool retrievable = false);
// The stages of one permutations.inc line, expanded with its #defines.
std::vector<ShaderStage> program_stages(const ProgramInfo& info);

class ProgramBinaryCache;

class ProgramCache {
public:
    // `binaries`: the engine's program-binary cache (may be null or inactive), which outlives this.
    explicit ProgramCache(const Api& gl, ProgramBinaryCache* binaries = nullptr) : gl_(gl), binaries_(binaries) {}
    ~ProgramCache();
    ProgramCache(const ProgramCache&) = delete;
    ProgramCache& operator=(const ProgramCache&) = delete;

    // The program for `id`, building it if needed; 0 with `error` set on failure.
    GLuint get(ProgramId id, std::string& error);
    // The program if it was built already, else 0.
    GLuint built(ProgramId id) const { return programs_[static_cast<size_t>(id)]; }
    // How many programs have been linked so far.
    uint32_t built_count() const {
        uint32_t n = 0;
        for (GLuint p : programs_) n += p != 0 ? 1u : 0u;
        return n;
    }

private:
    const Api& gl_;
    ProgramBinaryCache* binaries_;
    std::array<GLuint, static_cast<size_t>(ProgramId::count)> programs_{};
};

}  // namespace pf::gl
