#include "gl/program_binary_cache.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

#include "gl/implementation.h"
#include "pf/pf_version.h"

namespace pf::gl {

namespace {
constexpr size_t kHeaderBytes = sizeof(ProgramBlobHeader);
// load's first buffer: most programs' binaries fit, larger ones take a second call.
constexpr size_t kFirstCapacity = size_t(256) << 10;

uint64_t hash_string(const std::string& s, uint64_t hash) {
    return fnv1a64(s.c_str(), s.size() + 1, hash);  // with its terminator: "ab"+"c" differs from "a"+"bc"
}
}  // namespace

uint64_t fnv1a64(const void* data, size_t size, uint64_t hash) {
    const auto* p = static_cast<const uint8_t*>(data);
    for (size_t i = 0; i < size; ++i) {
        hash ^= p[i];
        hash *= 0x100000001b3ull;
    }
    return hash;
}

ProgramBinaryCache::ProgramBinaryCache(const Api& gl, const pf_program_cache& callbacks, const Log& log)
    : gl_(gl), callbacks_(callbacks), log_(log) {
    if (!callbacks_.load && !callbacks_.store) return;
    GLint count = 0;
    gl_.GetIntegerv(GL_NUM_PROGRAM_BINARY_FORMATS, &count);
    if (count <= 0) {
        log_.info("program cache: this GL offers no program binary format (GL_NUM_PROGRAM_BINARY_FORMATS is 0; Mesa "
                  "offers one only while its own shader cache is on): programs are compiled from source and the "
                  "cache is not called");
        return;
    }
    formats_.assign(size_t(count), 0);
    gl_.GetIntegerv(GL_PROGRAM_BINARY_FORMATS, formats_.data());
    for (GLenum name : {GL_VENDOR, GL_RENDERER, GL_VERSION}) identity_hash_ = hash_string(implementation_string(gl_, name), identity_hash_);
    identity_hash_ = hash_string(PF_VERSION_STRING, identity_hash_);
    active_ = true;
}

std::string ProgramBinaryCache::key(const std::vector<ShaderStage>& stages, const std::string& name, uint64_t* hash) const {
    uint64_t h = hash_string(name, identity_hash_);
    for (const ShaderStage& s : stages) {
        const uint32_t type = s.type;
        h = fnv1a64(&type, sizeof type, h);
        h = hash_string(s.source.text, h);
    }
    if (hash) *hash = h;
    char digits[17];
    std::snprintf(digits, sizeof digits, "%016llx", static_cast<unsigned long long>(h));
    return "pflip-" + name + "-" + digits;
}

GLuint ProgramBinaryCache::get_or_build(const std::vector<ShaderStage>& stages, const std::string& name,
                                        std::string& error) {
    for (const ShaderStage& s : stages) {
        if (!s.source.error.empty()) return build_program(gl_, stages, name, error);  // reports the error
    }
    uint64_t hash = 0;
    const std::string k = key(stages, name, &hash);
    if (GLuint program = load(k, hash, name)) {
        ++counts_.loaded;
        return program;
    }
    const GLuint program = build_program(gl_, stages, name, error, callbacks_.store != nullptr);
    if (!program) return 0;
    ++counts_.compiled;
    store(program, k, hash, name);
    return program;
}

void ProgramBinaryCache::reject(const std::string& name, const std::string& why) {
    ++counts_.rejected;
    log_.warning("program cache: the blob of " + name + " is not used (" + why + "); compiling from source");
}

GLuint ProgramBinaryCache::load(const std::string& key, uint64_t hash, const std::string& name) {
    if (!callbacks_.load) return 0;
    if (buffer_.size() < kFirstCapacity) buffer_.resize(kFirstCapacity);
    size_t size = callbacks_.load(callbacks_.user, key.c_str(), buffer_.data(), buffer_.size());
    if (size == 0) return 0;
    if (size > buffer_.size()) {  // a larger blob: once more with room for it
        buffer_.resize(size);
        const size_t again = callbacks_.load(callbacks_.user, key.c_str(), buffer_.data(), buffer_.size());
        if (again == 0) return 0;
        if (again > buffer_.size()) {
            reject(name, "load returned " + std::to_string(again) + " bytes after " + std::to_string(size));
            return 0;
        }
        size = again;
    }
    if (size < kHeaderBytes) {
        reject(name, std::to_string(size) + " bytes, shorter than its header");
        return 0;
    }
    ProgramBlobHeader h;
    std::memcpy(&h, buffer_.data(), kHeaderBytes);
    if (h.magic != ProgramBlobHeader::kMagic) {
        reject(name, "not a pflip program blob");
        return 0;
    }
    if (h.version != ProgramBlobHeader::kVersion) {
        reject(name, "blob format " + std::to_string(h.version) + ", this pflip writes " +
                         std::to_string(ProgramBlobHeader::kVersion));
        return 0;
    }
    if (h.key_hash != hash) {
        reject(name, "made for another key");
        return 0;
    }
    if (h.payload_size != size - kHeaderBytes) {
        reject(name, "its header says " + std::to_string(h.payload_size) + " bytes of binary, it holds " +
                         std::to_string(size - kHeaderBytes));
        return 0;
    }
    const uint8_t* payload = buffer_.data() + kHeaderBytes;
    if (fnv1a64(payload, size_t(h.payload_size)) != h.payload_checksum) {
        reject(name, "checksum mismatch");
        return 0;
    }
    // glProgramBinary raises GL_INVALID_ENUM for a format the GL does not offer: check first.
    if (std::find(formats_.begin(), formats_.end(), GLint(h.binary_format)) == formats_.end()) {
        reject(name, "binary format " + hex(h.binary_format) + " is not offered by this GL");
        return 0;
    }
    if (h.payload_size > size_t(INT32_MAX)) {
        reject(name, "binary too large");
        return 0;
    }
    const GLuint program = gl_.CreateProgram();
    gl_.ProgramBinary(program, h.binary_format, payload, GLsizei(h.payload_size));
    GLint ok = GL_FALSE;
    gl_.GetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        gl_.DeleteProgram(program);
        reject(name, "the driver refused the binary (another driver or version)");
        return 0;
    }
    return program;
}

void ProgramBinaryCache::store(GLuint program, const std::string& key, uint64_t hash, const std::string& name) {
    if (!callbacks_.store) return;
    GLint length = 0;
    gl_.GetProgramiv(program, GL_PROGRAM_BINARY_LENGTH, &length);
    if (length <= 0) {
        if (!empty_binary_logged_) log_.info("program cache: the driver returned no binary for " + name + "; not stored");
        empty_binary_logged_ = true;
        return;
    }
    std::vector<uint8_t> blob(kHeaderBytes + size_t(length));
    GLsizei written = 0;
    GLenum format = 0;
    gl_.GetProgramBinary(program, length, &written, &format, blob.data() + kHeaderBytes);
    if (written <= 0) return;
    blob.resize(kHeaderBytes + size_t(written));
    ProgramBlobHeader h;
    h.binary_format = format;
    h.key_hash = hash;
    h.payload_size = uint64_t(written);
    h.payload_checksum = fnv1a64(blob.data() + kHeaderBytes, size_t(written));
    std::memcpy(blob.data(), &h, kHeaderBytes);
    callbacks_.store(callbacks_.user, key.c_str(), blob.data(), blob.size());
    ++counts_.stored;
}

}  // namespace pf::gl
