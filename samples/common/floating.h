// Obstacles the samples float, as an engine's rigid bodies would: each frame the body's
// translation is integrated from the force the liquid exerts on it (pf_get_obstacle_force, read
// back a few frames late without stalling), its weight, and a linear damping (the engine side
// of the coupling, which the force's lag makes necessary for light bodies; see
// tests/engine/test_obstacles.cpp), and the new pose and velocity go back through
// pf_set_obstacle. Rotation is not integrated (the bodies keep their orientation).
// A body the user holds (the viewer's mouse drag) is not integrated: the application sets its
// pose and velocity (set_pose) and the body goes on from there when let go.
#pragma once

#include <pf/pf.h>

#include <vector>

namespace pfs {

class FloatingBodies {
public:
    /// Floats obstacle `id` (as added: `obstacle`) with the given density (kg/m^3).
    void add(uint32_t id, const pf_obstacle& obstacle, double density);
    /// One frame: integrates every body over frame_dt under `gravity` and sets it in sim.
    /// Returns the first error of pf_set_obstacle / pf_get_obstacle_force (PF_OK if none).
    pf_result step(pf_sim* sim, float frame_dt, const float gravity[3]);
    bool empty() const { return bodies_.empty(); }

    /// Replaces the pose and velocity of floating obstacle `id` (no-op for others); the caller
    /// gives pflip the same pose.
    void set_pose(uint32_t id, const pf_obstacle& obstacle);
    /// A held body is left out of step(): the application moves it.
    void set_held(uint32_t id, bool held);
    /// The poses pflip holds now: `placed` (the application's poses, ids[i] naming placed[i])
    /// with each floating obstacle's pose in its place.
    std::vector<pf_obstacle> poses(const std::vector<pf_obstacle>& placed, const std::vector<uint32_t>& ids) const;

private:
    struct Body {
        uint32_t id;
        pf_obstacle obstacle;
        double mass;
        bool held = false;
    };
    const Body* find(uint32_t id) const;
    Body* find(uint32_t id);
    std::vector<Body> bodies_;
};

/// Volume of an obstacle's shape, m^3 (an SDF obstacle: its box).
double obstacle_volume(const pf_obstacle& obstacle);

} // namespace pfs
