// Writes every permutation of shaders/permutations.inc, expanded exactly as the library
// hands it to the GL, to <dir>/<id>.<stage> for glslangValidator.
#include <cstdio>
#include <fstream>
#include <string>

#include "gl/shader_source.h"

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
        const pf::gl::ExpandedSource src = pf::gl::expand_shader(p.file, p.defines);
        if (!src.error.empty()) {
            std::fprintf(stderr, "%s: %s\n", p.id, src.error.c_str());
            ++failures;
            continue;
        }
        const std::string file = p.file;
        const std::string path = dir + "/" + p.id + file.substr(file.rfind('.'));
        std::ofstream(path) << src.text;
        std::printf("%s <- %s %s\n", path.c_str(), p.file, p.defines);
    }
    return failures ? 1 : 0;
}
