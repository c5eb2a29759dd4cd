// Whitewater (PF_FEATURE_WHITEWATER), second pass, per particle slot: ages last step's
// particles, drops those whose life is over or that are inside a SOLID cell, moves the rest by
// their kind (the liquid fraction around them, whitewater.glsl; Ihmsen et al. 2012, section 5)
// and appends them to this step's buffers:
//   spray  (little liquid around): ballistic, v' = (v + dt g) / (1 + dt k_air);
//   foam   (at the surface): carried by the liquid, v' = u;
//   bubble (inside): v' = u + (v - u) exp(-k_drag dt) - dt k_buoyancy g.
// A particle that would leave the domain or enter a SOLID cell (an obstacle) stops at that wall:
// the move is taken axis by axis, an axis whose end point would lie in a SOLID cell keeps its
// coordinate, and that velocity component is zeroed, so spray hitting an obstacle stays outside
// and slides along it, as at the domain's walls. Only end points are tested: a particle moving
// more than a cell in a step can cross an obstacle one cell thick.
#include "effects/whitewater/whitewater.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_WW_IN_POS) readonly buffer InPos { vec4 in_pos[]; };
layout(std430, binding = PF_SLOT_WW_IN_VEL) readonly buffer InVel { vec4 in_vel[]; };
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer CellType { uint cell_type[]; };
layout(std430, binding = PF_SLOT_WW_FRACTION) readonly buffer Fraction { float fraction[]; };
layout(std430, binding = PF_SLOT_WW_OUT_POS) writeonly buffer OutPos { vec4 out_pos[]; };
layout(std430, binding = PF_SLOT_WW_OUT_VEL) writeonly buffer OutVel { vec4 out_vel[]; };
layout(std430, binding = PF_SLOT_WW_STATE) buffer State { uint state[]; };
layout(location = PF_LOC_WW_MOTION) uniform vec4 u_motion;  // dt, bubble buoyancy, bubble drag, spray drag

bool solid(ivec3 c) { return cell_inside(c) && PF_CELL_KIND(cell_type[cell_index(c)]) == PF_CELL_SOLID; }

void main() {
    uint i = flat_id();
    if (i >= state[PF_WW_LIVE]) return;
    float dt = u_motion.x;
    vec4 p = in_pos[i];
    float life = p.w - dt;
    if (!(life > 0.0)) return;
    ivec3 c = ivec3(floor(grid_coord(p.xyz)));
    if (!cell_inside(c) || solid(c)) return;
    float kind = kind_for(fraction[cell_index(c)]);
    vec3 v = in_vel[i].xyz;
    vec3 g = sim.gravity.xyz;
    if (kind == PF_WW_SPRAY) {
        v = (v + dt * g) / (1.0 + dt * u_motion.w);
    } else {
        vec3 u = sample_velocity(p.xyz);
        v = kind == PF_WW_FOAM ? u : u + (v - u) * exp(-u_motion.z * dt) - dt * u_motion.y * g;
    }
    vec3 x = p.xyz;
    for (int a = 0; a < 3; ++a) {
        vec3 trial = x;
        trial[a] += dt * v[a];
        if (solid(ivec3(floor(grid_coord(trial)))))
            v[a] = 0.0;
        else
            x = trial;
    }
    vec3 kept = keep_in_domain(x);
    v = mix(v, vec3(0.0), notEqual(kept, x));
    if (any(isnan(kept)) || any(isnan(v))) return;
    uint slot = atomicAdd(state[PF_WW_NEXT], 1u);
    out_pos[slot] = vec4(kept, life);
    out_vel[slot] = vec4(v, kind);
}
