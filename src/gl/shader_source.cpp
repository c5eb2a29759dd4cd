#include "gl/shader_source.h"

#include <cstring>
#include <regex>
#include <set>
#include <sstream>

namespace pf::gl {

namespace {
const std::vector<ProgramInfo> kPrograms = {
#define PF_PROGRAM(id, file, defines) {#id, file, nullptr, defines},
#define PF_RASTER_PROGRAM(id, vertex, fragment, defines) {#id, vertex, fragment, defines},
#include "permutations.inc"
#undef PF_RASTER_PROGRAM
#undef PF_PROGRAM
};

bool expand_into(const std::string& path, ExpandedSource& out, std::set<std::string>& included,
                 std::vector<std::string>& stack) {
    const char* text = find_shader_file(path);
    if (!text) {
        out.error = "shader file not found: " + path +
                    (stack.empty() ? std::string() : " (included from " + stack.back() + ")");
        return false;
    }
    for (const std::string& open : stack) {
        if (open == path) {
            out.error = "include cycle through " + path;
            return false;
        }
    }
    included.insert(path);
    stack.push_back(path);
    const int file_no = static_cast<int>(out.files.size());
    out.files.push_back(path);
    out.text += "#line 1 " + std::to_string(file_no) + "\n";

    std::istringstream lines(text);
    std::string line;
    int line_no = 0;
    while (std::getline(lines, line)) {
        ++line_no;
        const size_t first = line.find_first_not_of(" \t");
        if (first != std::string::npos && line.compare(first, 8, "#include") == 0) {
            const size_t q0 = line.find('"', first);
            const size_t q1 = q0 == std::string::npos ? q0 : line.find('"', q0 + 1);
            if (q1 == std::string::npos) {
                out.error = path + ":" + std::to_string(line_no) + ": malformed #include";
                return false;
            }
            const std::string inc = line.substr(q0 + 1, q1 - q0 - 1);
            if (!included.count(inc)) {
                if (!expand_into(inc, out, included, stack)) return false;
            }
            out.text += "#line " + std::to_string(line_no + 1) + " " + std::to_string(file_no) + "\n";
            continue;
        }
        out.text += line;
        out.text += '\n';
    }
    stack.pop_back();
    return true;
}
}  // namespace

const ProgramInfo& program_info(ProgramId id) { return kPrograms[static_cast<size_t>(id)]; }

const std::vector<ProgramInfo>& all_programs() { return kPrograms; }

const char* find_shader_file(const std::string& path) {
    for (unsigned i = 0; i < kEmbeddedShaderFileCount; ++i) {
        if (path == kEmbeddedShaderFiles[i].path) return kEmbeddedShaderFiles[i].text;
    }
    return nullptr;
}

ExpandedSource expand_shader(const std::string& file, const std::string& defines) {
    ExpandedSource out;
    out.text = "#version 430 core\n";
    if (!defines.empty()) {
        out.text += defines;
        if (defines.back() != '\n') out.text += '\n';
    }
    std::set<std::string> included;
    std::vector<std::string> stack;
    if (!expand_into(file, out, included, stack)) out.text.clear();
    return out;
}

std::string annotate_log(const std::string& log, const std::vector<std::string>& files) {
    // Mesa writes "0:12(3): error", NVIDIA "0(12) : error": both start with the source number.
    static const std::regex kLocation(R"((^|\n)(\d+)([:(])(\d+))");
    std::string result;
    auto begin = std::sregex_iterator(log.begin(), log.end(), kLocation);
    size_t last = 0;
    for (auto it = begin; it != std::sregex_iterator(); ++it) {
        const std::smatch& m = *it;
        const size_t file_no = std::stoul(m[2].str());
        if (file_no >= files.size()) continue;
        result.append(log, last, m.position(0) - last);
        result += m[1].str() + files[file_no] + ":" + m[4].str();
        last = m.position(0) + m.length(0);
    }
    result.append(log, last, std::string::npos);
    return result;
}

}  // namespace pf::gl
