// GL 3D textures made from SDF grids (sdf_file.h) for the library's SDF obstacles. They are the
// engine's objects: pf samples them and never deletes them, so the samples own them here and
// delete them when done with the simulation. The header is GL-free (scene.h includes it); the
// code is in sdf_texture.cpp, which uses the app's GL loader (glad, after gladLoadGL).
#pragma once

#include "sdf_file.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace pfs {

class SdfTextures {
public:
    SdfTextures() = default;
    /// Deletes the textures (the GL context that made them must be current).
    ~SdfTextures();
    SdfTextures(SdfTextures&& other) noexcept : names_(std::exchange(other.names_, {})) {}
    SdfTextures& operator=(SdfTextures&& other) noexcept;
    SdfTextures(const SdfTextures&) = delete;
    SdfTextures& operator=(const SdfTextures&) = delete;

    /// Uploads `grid` as a new GL_TEXTURE_3D of its size (width nx, height ny, depth nz), format
    /// GL_R32F or GL_R16F as the file stored it, one level; returns its name. GL state the
    /// upload touches (the 3D binding of the active unit, the pixel-unpack buffer and alignment)
    /// is restored. Throws pfs::Error when GL is not loaded or reports an error.
    uint32_t add(const SdfGrid& grid, const std::string& label);
    size_t size() const { return names_.size(); }

private:
    void release();
    std::vector<uint32_t> names_;
};

} // namespace pfs
