#include "driven.h"

#include <cmath>

namespace pfs {

namespace {
constexpr double kTwoPi = 6.28318530717958647692;
} // namespace

void DrivenObstacles::position_at(const pf_obstacle& rest, const Oscillation& motion, double t, float out[3]) {
    const double s = std::sin(kTwoPi * t / double(motion.period));
    for (int a = 0; a < 3; ++a) out[a] = float(double(rest.position[a]) + double(motion.amplitude[a]) * s);
}

void DrivenObstacles::add(uint32_t id, const pf_obstacle& obstacle, const Oscillation& motion) {
    bodies_.push_back(Body{id, obstacle, motion, obstacle});
}

pf_result DrivenObstacles::step(pf_sim* sim, float frame_dt) {
    for (Body& b : bodies_) {
        float now[3], next[3];
        position_at(b.rest, b.motion, time_, now);
        position_at(b.rest, b.motion, time_ + double(frame_dt), next);
        pf_obstacle& o = b.current;
        for (int a = 0; a < 3; ++a) {
            o.position[a] = now[a];
            o.velocity[a] = frame_dt > 0.0f ? (next[a] - now[a]) / frame_dt : 0.0f;
        }
        if (pf_result r = pf_set_obstacle(sim, b.id, &o); r != PF_OK) return r;
    }
    time_ += double(frame_dt);
    return PF_OK;
}

std::vector<pf_obstacle> DrivenObstacles::poses(const std::vector<pf_obstacle>& placed,
                                                const std::vector<uint32_t>& ids) const {
    std::vector<pf_obstacle> out = placed;
    for (size_t i = 0; i < out.size() && i < ids.size(); ++i)
        for (const Body& b : bodies_)
            if (b.id == ids[i]) out[i] = b.current;
    return out;
}

} // namespace pfs
