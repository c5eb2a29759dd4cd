// Particle export to PLY (Stanford polygon format), the point-cloud format Blender, Houdini,
// MeshLab and CloudCompare all read: one vertex per particle with the float properties
// x y z vx vy vz (velocities become a point attribute named after them).
#pragma once

#include <cstdint>
#include <string>

namespace pfs {

enum class PlyFormat {
    binary_little_endian, ///< compact and exact (the default)
    ascii,                ///< readable, %.9g keeps every float exact
};

/// Writes n particles to path: xyz and vel are 3n floats each (vel may be NULL: zeros).
/// comment (one line, may be empty) goes into the header. Returns false on failure (errno
/// tells why).
bool write_ply_particles(const std::string& path, const float* xyz, const float* vel, uint32_t n,
                         PlyFormat format, const std::string& comment);

} // namespace pfs
