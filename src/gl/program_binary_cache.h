// The engine's program-binary cache (pf_sim_desc.program_cache): before compiling a program,
// pflip asks the engine for the driver binary stored under the program's key and links from it;
// after compiling one, it hands the binary to the engine. A blob is never trusted: its header
// (our magic and format, the key's hash, the payload's length and checksum) is checked, the GL
// must offer its binary format, and the program must link from it; anything else is logged and
// the program compiled from source and stored again, replacing the bad blob. One per
// simulation (its programs and its renderer's); the callbacks run on the calling thread.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "api/log.h"
#include "gl/gl.h"
#include "gl/program.h"
#include "pf/pf.h"

namespace pf::gl {

// 64-bit FNV-1a over `size` bytes, continuing from `hash` (the offset basis to start).
constexpr uint64_t kFnv1aBasis = 0xcbf29ce484222325ull;
uint64_t fnv1a64(const void* data, size_t size, uint64_t hash = kFnv1aBasis);

// What every stored blob starts with (host byte order: the blob is only ever read back by the
// same machine's driver).
struct ProgramBlobHeader {
    static constexpr uint32_t kMagic = 0x42504650u;  // "PFPB"
    static constexpr uint32_t kVersion = 1;
    uint32_t magic = kMagic;
    uint32_t version = kVersion;
    uint32_t binary_format = 0;   // the GLenum glGetProgramBinary returned
    uint32_t reserved = 0;
    uint64_t key_hash = 0;        // the hash the key was made from
    uint64_t payload_size = 0;    // bytes of driver binary after the header
    uint64_t payload_checksum = 0;  // fnv1a64 of those bytes
};
static_assert(sizeof(ProgramBlobHeader) == 40, "the stored layout");

class ProgramBinaryCache {
public:
    // Learns the GL's binary formats and the driver's identity. With no callback, or a GL that
    // offers no binary format (logged once), the cache stays inactive and nothing is called.
    ProgramBinaryCache(const Api& gl, const pf_program_cache& callbacks, const Log& log);

    bool active() const { return active_; }
    // The key of a program: "pflip-<name>-<16 hex digits>", the digits a hash of the driver
    // (GL_VENDOR, GL_RENDERER, GL_VERSION), pflip's version, the name and every stage's type
    // and full source (permutation #defines included).
    std::string key(const std::vector<ShaderStage>& stages, const std::string& name, uint64_t* hash = nullptr) const;
    // The program, linked from the engine's blob when it holds a good one, else compiled from
    // source (and stored). 0 with `error` set when compiling fails.
    GLuint get_or_build(const std::vector<ShaderStage>& stages, const std::string& name, std::string& error);

    struct Counts {
        uint32_t loaded = 0;    // programs linked from a blob
        uint32_t compiled = 0;  // programs compiled from source while active
        uint32_t rejected = 0;  // blobs found but not used (stale, damaged, foreign)
        uint32_t stored = 0;    // blobs handed to store
    };
    const Counts& counts() const { return counts_; }

private:
    GLuint load(const std::string& key, uint64_t hash, const std::string& name);
    void store(GLuint program, const std::string& key, uint64_t hash, const std::string& name);
    // Logs why the blob of `name` is not used and counts it.
    void reject(const std::string& name, const std::string& why);

    const Api& gl_;
    pf_program_cache callbacks_;
    const Log& log_;
    bool active_ = false;
    bool empty_binary_logged_ = false;
    uint64_t identity_hash_ = kFnv1aBasis;  // driver and pflip version, the start of every key's hash
    std::vector<GLint> formats_;            // GL_PROGRAM_BINARY_FORMATS
    std::vector<uint8_t> buffer_;           // load's buffer, kept between programs
    Counts counts_;
};

}  // namespace pf::gl
