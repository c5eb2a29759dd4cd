"""Turns the code blocks of the README and docs/integration.md into sources that are compiled
against the installed package, exactly as written (tests/consumer/consumer_test.cmake, MODE
snippets).

Each page's ```c blocks go, in order and each nested in the one before (so a later block sees the
variables an earlier one declared, as a reader does), into one function of <page>.c, after a
prelude that declares what the blocks take from the engine (its loader, logger, framebuffer...).
`#include` lines move to the top of the file. Each ```cmake block that calls find_package(pflip)
becomes a project, <page>_cmake_<n>/CMakeLists.txt, in which the engine's target exists.

Usage: snippets.py OUT_DIR PAGE...   (prints the files written, one per line)
"""
import os
import re
import sys

FENCE = re.compile(r"^```([a-z]*)\s*$")

# What the snippets name but an engine provides. Declared, not defined: the sources are compiled,
# not linked (nothing here may stand in for pflip's own API).
C_PRELUDE = """\
#include <stddef.h>
#include <stdint.h>
#include <pf/pf.h>
typedef void (*GLFWglproc)(void);
GLFWglproc glfwGetProcAddress(const char* name);
void my_log(void* user, pf_log_level level, pf_result code, const char* message);
extern void* my_engine;
void draw_world(uint32_t framebuffer);
extern uint32_t engine_fbo, engine_color_tex, engine_depth_tex, sky_cubemap;
extern float frame_dt;
size_t my_load(void* user, const char* key, void* data, size_t capacity);
void my_store(void* user, const char* key, const void* data, size_t size);
extern void* my_blob_store;
"""

CMAKE_PRELUDE = """\
cmake_minimum_required(VERSION 3.21)
project(snippet LANGUAGES C)
file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/engine.c" "#include <pf/pf.h>\\nint main(void) { return (int)pf_version() == 0; }\\n")
add_executable(my_engine "${CMAKE_CURRENT_BINARY_DIR}/engine.c")
"""


def blocks(path):
    """(language, first line number, text) of every fenced block in path."""
    out, lang, start, body = [], None, 0, []
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            m = FENCE.match(line.rstrip("\n"))
            if lang is None and m:
                lang, start, body = m.group(1), n + 1, []
            elif lang is not None and line.rstrip("\n") == "```":
                out.append((lang, start, "".join(body)))
                lang = None
            elif lang is not None:
                body.append(line)
    if lang is not None:
        sys.exit(f"{path}:{start}: a code block is not closed")
    return out


def main():
    out_dir, pages = sys.argv[1], sys.argv[2:]
    os.makedirs(out_dir, exist_ok=True)
    for page in pages:
        name = re.sub(r"\W", "_", os.path.splitext(os.path.basename(page))[0]).lower()
        found = blocks(page)
        c_blocks = [(start, text) for lang, start, text in found if lang == "c"]
        if c_blocks:
            includes, body = [], []
            for depth, (start, text) in enumerate(c_blocks):
                lines = text.splitlines()
                includes += [l for l in lines if l.startswith("#include")]
                body.append(f'{{ /* {page}:{start} */\n#line {start} "{page}"\n')
                body += [l + "\n" for l in lines if not l.startswith("#include")]
            body.append("}" * len(c_blocks) + "\n")
            path = os.path.join(out_dir, name + ".c")
            with open(path, "w", encoding="utf-8") as f:
                f.write(C_PRELUDE + "\n".join(includes) + "\n")
                f.write(f"void snippets_of_{name}(void);\nvoid snippets_of_{name}(void) {{\n")
                f.write("".join(body) + "}\n")
            print(path)
        cmake_blocks = [(start, text) for lang, start, text in found
                        if lang == "cmake" and "find_package(pflip" in text]
        for i, (start, text) in enumerate(cmake_blocks):
            project = os.path.join(out_dir, f"{name}_cmake_{i}")
            os.makedirs(project, exist_ok=True)
            with open(os.path.join(project, "CMakeLists.txt"), "w", encoding="utf-8") as f:
                f.write(CMAKE_PRELUDE + f"# {page}:{start}\n" + text)
            print(project)


if __name__ == "__main__":
    main()
