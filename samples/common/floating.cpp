#include "floating.h"

#include <cmath>

namespace pfs {

namespace {
constexpr double kPi = 3.14159265358979323846;
// Damping rate (1/s) of the bodies' velocity: about half-critical for a crate bobbing at a few
// hertz, as in the engine test's floating box.
constexpr double kDamping = 3.0;
} // namespace

double obstacle_volume(const pf_obstacle& o) {
    switch (o.shape) {
        case PF_OBSTACLE_SPHERE: return 4.0 / 3.0 * kPi * std::pow(double(o.radius), 3);
        case PF_OBSTACLE_CAPSULE:
            return kPi * double(o.radius) * o.radius * 2.0 * o.half_height + 4.0 / 3.0 * kPi * std::pow(double(o.radius), 3);
        default: return 8.0 * double(o.half_extents[0]) * o.half_extents[1] * o.half_extents[2];
    }
}

void FloatingBodies::add(uint32_t id, const pf_obstacle& obstacle, double density) {
    bodies_.push_back(Body{id, obstacle, density * obstacle_volume(obstacle)});
}

const FloatingBodies::Body* FloatingBodies::find(uint32_t id) const {
    for (const Body& b : bodies_)
        if (b.id == id) return &b;
    return nullptr;
}

FloatingBodies::Body* FloatingBodies::find(uint32_t id) {
    return const_cast<Body*>(static_cast<const FloatingBodies*>(this)->find(id));
}

void FloatingBodies::set_pose(uint32_t id, const pf_obstacle& obstacle) {
    if (Body* b = find(id)) b->obstacle = obstacle;
}

void FloatingBodies::set_held(uint32_t id, bool held) {
    if (Body* b = find(id)) b->held = held;
}

std::vector<pf_obstacle> FloatingBodies::poses(const std::vector<pf_obstacle>& placed,
                                               const std::vector<uint32_t>& ids) const {
    std::vector<pf_obstacle> out = placed;
    for (size_t i = 0; i < out.size() && i < ids.size(); ++i)
        if (const Body* b = find(ids[i])) out[i] = b->obstacle;
    return out;
}

pf_result FloatingBodies::step(pf_sim* sim, float frame_dt, const float gravity[3]) {
    for (Body& b : bodies_) {
        if (b.held) continue;
        pf_obstacle_force f{};
        if (pf_result r = pf_get_obstacle_force(sim, b.id, &f); r != PF_OK) return r;
        pf_obstacle& o = b.obstacle;
        for (int a = 0; a < 3; ++a) {
            const double accel = (f.step ? double(f.force[a]) / b.mass : 0.0) + gravity[a] - kDamping * o.velocity[a];
            o.velocity[a] = float(o.velocity[a] + accel * frame_dt);
            o.position[a] = float(o.position[a] + double(o.velocity[a]) * frame_dt);
        }
        if (pf_result r = pf_set_obstacle(sim, b.id, &o); r != PF_OK) return r;
    }
    return PF_OK;
}

} // namespace pfs
