// Writes every stage of every permutation of shaders/permutations.inc, expanded exactly as the
// library hands it to the GL, to <dir>/<id>.<stage> (comp, or vert and frag) for glslangValidator.
#include <cstdio>
#include <fstream>
#include <string>

#include "gl/program.h"
#include "gl/shader_source.h"

namespace {
const char* extension(GLenum type) {
    switch (type) {
        case GL_COMPUTE_SHADER: return ".comp";
        case GL_VERTEX_SHADER: return ".vert";
        case GL_FRAGMENT_SHADER: return ".frag";
        default: return ".glsl";
    }
}
}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s <output dir>\n", argv[0]);
        return 2;
    }
    const std::string dir = argv[1];
    std::string mkdir = "mkdir -p '" + dir + "'";
    if (std::system(mkdir.c_str()) != 0) return 1;
    int failures = 0;
    for (const pf::gl::ProgramInfo& p : pf::gl::all_programs()) {
        for (const pf::gl::ShaderStage& stage : pf::gl::program_stages(p)) {
            if (!stage.source.error.empty()) {
                std::fprintf(stderr, "%s: %s\n", p.id, stage.source.error.c_str());
                ++failures;
                continue;
            }
            const std::string path = dir + "/" + p.id + extension(stage.type);
            std::ofstream(path) << stage.source.text;
            std::printf("%s <- %s%s%s %s\n", path.c_str(), p.file, p.fragment ? " + " : "",
                        p.fragment ? p.fragment : "", p.defines);
        }
    }
    return failures ? 1 : 0;
}
