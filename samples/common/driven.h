// Obstacles the samples move along a scripted path, as an engine's animated props (a wave
// maker, a bobbing buoy): a periodic translation about the scene's position,
// p(t) = p0 + amplitude sin(2 pi t / period). Each frame the pose at the frame's start and the
// velocity that carries it to the next frame's pose, (p(t + dt) - p(t)) / dt, go to pflip
// through pf_set_obstacle, which is what an engine does for an animated obstacle (pf.h).
#pragma once

#include <pf/pf.h>

#include <vector>

namespace pfs {

/// A periodic translation: amplitude (m, per axis) and period (s, > 0).
struct Oscillation {
    float amplitude[3] = {0, 0, 0};
    float period = 0;  ///< 0: not driven
};

class DrivenObstacles {
public:
    /// Drives obstacle `id` (as added: `obstacle`, at its rest position) along `motion`.
    void add(uint32_t id, const pf_obstacle& obstacle, const Oscillation& motion);
    /// One frame from the current time: sets each obstacle's pose and velocity in sim, then
    /// advances the time by frame_dt. Returns the first error of pf_set_obstacle (PF_OK if none).
    pf_result step(pf_sim* sim, float frame_dt);
    bool empty() const { return bodies_.empty(); }
    double time() const { return time_; }

    /// The poses pflip holds now: `placed` (ids[i] naming placed[i]) with each driven obstacle's
    /// pose in its place.
    std::vector<pf_obstacle> poses(const std::vector<pf_obstacle>& placed, const std::vector<uint32_t>& ids) const;

    /// Position of a driven obstacle at time t (s) from its rest position.
    static void position_at(const pf_obstacle& rest, const Oscillation& motion, double t, float out[3]);

private:
    struct Body {
        uint32_t id;
        pf_obstacle rest;     // as added
        Oscillation motion;
        pf_obstacle current;  // as last set
    };
    std::vector<Body> bodies_;
    double time_ = 0.0;
};

} // namespace pfs
