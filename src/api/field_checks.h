// Small checks the argument validators share (src/api/validate.cpp and each effect's
// <name>_api.cpp): finite vectors, numbers in messages, a turned shape's bounds.
#pragma once
#include <cmath>
#include <cstdio>
#include <string>

namespace pf {

inline bool finite3(const float v[3]) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }
inline bool finite4(const float v[4]) { return finite3(v) && std::isfinite(v[3]); }
inline bool finite_n(const float* v, int n) {
    for (int i = 0; i < n; ++i)
        if (!std::isfinite(v[i])) return false;
    return true;
}

// A number as a message shows it (%g).
inline std::string number_string(double v) {
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%g", v);
    return buf;
}

// The axis-aligned bounds [lo, hi] (world m) of a box of half sizes `half` (local axes) at
// `position`, turned by quaternion `rotation` (x, y, z, w; (0, 0, 0, 0) reads as the identity).
inline void shape_bounds(const float position[3], const float rotation[4], const double half[3], double lo[3],
                         double hi[3]) {
    double q[4] = {rotation[0], rotation[1], rotation[2], rotation[3]};
    const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (n > 0.0) {
        for (double& c : q) c /= n;
    } else {
        q[3] = 1.0;
    }
    const double x = q[0], y = q[1], z = q[2], w = q[3];
    const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                            {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                            {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
    for (int a = 0; a < 3; ++a) {
        const double ext = std::abs(r[a][0]) * half[0] + std::abs(r[a][1]) * half[1] + std::abs(r[a][2]) * half[2];
        lo[a] = double(position[a]) - ext;
        hi[a] = double(position[a]) + ext;
    }
}

}  // namespace pf
