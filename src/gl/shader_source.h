// Shader sources embedded at build time and the small preprocessor that resolves
// `#include "path"` (each file once) and prepends the #version and permutation #defines.
#pragma once
#include <string>
#include <vector>

namespace pf::gl {

struct EmbeddedShaderFile {
    const char* path;  // relative to shaders/, e.g. "sim/classify.comp"
    const char* text;
};
extern const EmbeddedShaderFile kEmbeddedShaderFiles[];
extern const unsigned kEmbeddedShaderFileCount;

// One line of shaders/permutations.inc: a compute program (PF_PROGRAM: `file` is the .comp,
// `fragment` is null) or a raster program (PF_RASTER_PROGRAM: `file` is the .vert and
// `fragment` the .frag). `defines` go in front of every stage of the program.
struct ProgramInfo {
    const char* id;
    const char* file;
    const char* fragment;
    const char* defines;
};

enum class ProgramId {
#define PF_PROGRAM(id, file, defines) id,
#define PF_RASTER_PROGRAM(id, vertex, fragment, defines) id,
#include "permutations.inc"
#undef PF_RASTER_PROGRAM
#undef PF_PROGRAM
    count
};

const ProgramInfo& program_info(ProgramId id);
const std::vector<ProgramInfo>& all_programs();

// Text of an embedded file, or nullptr.
const char* find_shader_file(const std::string& path);

struct ExpandedSource {
    std::string text;                 // complete source, ready for glShaderSource
    std::vector<std::string> files;   // source-string numbers used in #line: index -> path
    std::string error;                // non-empty if expansion failed (missing include, cycle)
};

// Expands `file` with the given extra #define lines (may be empty).
ExpandedSource expand_shader(const std::string& file, const std::string& defines);

// Rewrites "0(12)"-style GL log locations into "sim/classify.comp:12" using the #line table.
std::string annotate_log(const std::string& log, const std::vector<std::string>& files);

}  // namespace pf::gl
