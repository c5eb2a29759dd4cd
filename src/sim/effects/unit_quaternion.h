// The orientation every effect object carries (pf.h: a quaternion (x, y, z, w), normalised
// internally, (0, 0, 0, 0) meaning the identity) as the unit quaternion its GPU record holds.
#pragma once
#include <array>
#include <cmath>

namespace pf {

// `q` validated finite; normalised in double precision, the zero quaternion as the identity.
inline std::array<float, 4> unit_quaternion(const float q[4]) {
    const double n = std::sqrt(double(q[0]) * q[0] + double(q[1]) * q[1] + double(q[2]) * q[2] + double(q[3]) * q[3]);
    if (!(n > 0.0)) return {0.0f, 0.0f, 0.0f, 1.0f};
    return {float(q[0] / n), float(q[1] / n), float(q[2] / n), float(q[3] / n)};
}

}  // namespace pf
