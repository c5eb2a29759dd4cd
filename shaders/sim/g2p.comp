// Grid-to-particle: PIC/FLIP blend v = (1-r) I(u) + r (v_p + I(u - u_old)) with the same
// clamped trilinear stencil as P2G. For a particle alone in its cell (spray), on a face the velocity
// update left to the extrapolation (between two AIR or two SOLID cells) P2G's u_old is other
// particles' velocity: there its FLIP value v_p + u - u_old is kept between v_p and u, else the
// difference fed its speed (docs/notes/2026-12-06-lone-particle-flip.md). How alone it is comes
// from the P2G weights on its cell's faces, so the rule fades in continuously. Non-finite results
// are zeroed and speeds above max_speed clamped (both flagged); the largest speed goes to the
// status buffer for the next frame's CFL estimate. Permutation PF_PIC_ONLY (flip ratio 0) skips
// u_old and the rule; PF_ORDERED walks the particles in the tiled P2G's order
// (common/particle_order.glsl); PF_SOLID_WALLS stops the stencil at obstacles
// (common/solid_walls.glsl).
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_PARTICLE_POS) readonly buffer Pos { vec4 pos[]; };
layout(std430, binding = PF_SLOT_PARTICLE_VEL) buffer Vel { vec4 vel[]; };
layout(std430, binding = PF_SLOT_FACE_VEL) readonly buffer FaceVel { float face_vel[]; };
#if !PF_PIC_ONLY
layout(std430, binding = PF_SLOT_FACE_VEL_OLD) readonly buffer FaceVelOld { float face_vel_old[]; };
layout(std430, binding = PF_SLOT_G2P_FACE_ACCUM) readonly buffer Accum { uint accum[]; };
#endif
layout(std430, binding = PF_SLOT_STATUS) buffer Status { uint status[]; };
#if PF_SOLID_WALLS || !PF_PIC_ONLY
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer Type { uint cell_type[]; };
#endif
#include "common/solid_walls.glsl"
#include "common/particle_velocity.glsl"
#include "common/particle_order.glsl"

#if !PF_PIC_ONLY
// Other particles' P2G weight at which the rule is off: about one more particle in the cell (a
// particle gives its cell's six faces 0.75 to 3 in all).
const float kCompany = 1.0;

float weight_sum(int face) {
    uint word = accum[accum_word(face, 1)];
    return sim.p2g_float_sums != 0u ? uintBitsToFloat(word) : float(int(word)) * sim.inv_weight_scale;
}

// 1 for a particle whose cell's faces hold no other particle's weight, falling linearly to 0 at
// kCompany. Its own weight on a face is P2G's stencil weight (0 off its stencil). Each axis's two
// faces are added first (mirror-exact); most particles have company on their cell's first pair.
float solitude(vec3 g) {
    ivec3 c = cell_of(g);
    float others = 0.0;
    for (int axis = 0; axis < 3; ++axis) {
        Stencil st = sampling_stencil(axis, g);
        float side[2];
        for (int k = 0; k < 2; ++k) {
            ivec3 f = c;
            f[axis] += k;
            ivec3 d = f - st.base;
            float own = all(greaterThanEqual(d, ivec3(0))) && all(lessThanEqual(d, ivec3(1))) ? stencil_weight(st.frac, d) : 0.0;
            side[k] = weight_sum(face_index(axis, f)) - own;
        }
        others += side[0] + side[1];
        if (others >= kCompany) return 0.0;
    }
    return min(1.0 - others / kCompany, 1.0);
}

// A face sim/velocity_update.comp gave no velocity (domain walls have one).
bool extrapolated_face(int axis, ivec3 f) {
    return !face_is_wall(axis, f) && face_left_to_extrapolation(PF_CELL_KIND(cell_type[cell_index(face_cell_below(axis, f))]),
                                                                PF_CELL_KIND(cell_type[cell_index(f)]));
}

// What the clamp changes in the FLIP delta of a particle at g with velocity v_own: per axis the
// stencil's sum of w (clamped - unclamped) over the extrapolated faces.
vec3 lone_correction(vec3 g, vec3 v_own) {
    vec3 out_sum = vec3(0.0);
    for (int axis = 0; axis < 3; ++axis) {
        Stencil st = sampling_stencil(axis, g);
        float term[8];
        for (int n = 0; n < 8; ++n) {
            ivec3 d = stencil_offset(n);
            term[n] = 0.0;
            if (!extrapolated_face(axis, st.base + d)) continue;
            int face = face_index(axis, st.base + d);
            float u = face_vel[face];
            float change = u - face_vel_old[face];
            float to_grid = u - v_own[axis];
            term[n] = stencil_weight(st.frac, d) * (clamp(change, min(to_grid, 0.0), max(to_grid, 0.0)) - change);
        }
        out_sum[axis] = mirror_sum(term);
    }
    return out_sum;
}
#endif

void main() {
    uint t = flat_id();
    if (t >= sim.particle_count) return;
    uint i = particle_slot(t);
    vec3 g = grid_coord(pos[i].xyz);
#if !PF_PIC_ONLY
    vec3 v_own = vel[i].xyz;
    float alone = solitude(g);
#endif
    vec3 v_pic = vec3(0.0);
    vec3 delta = vec3(0.0);
    for (int axis = 0; axis < 3; ++axis) {
        Stencil st = sampling_stencil(axis, g);
        float pic[8];
        float dif[8];
        for (int n = 0; n < 8; ++n) {
            ivec3 d = stencil_offset(n);
            float w = stencil_weight(st.frac, d);
            int face = face_index(axis, st.base + d);
            float u = face_vel[face];
            pic[n] = w * u;
#if PF_PIC_ONLY
            dif[n] = 0.0;
#else
            dif[n] = w * (u - face_vel_old[face]);
#endif
        }
        v_pic[axis] = mirror_sum(pic);
        delta[axis] = mirror_sum(dif);
    }
#if PF_PIC_ONLY
    vec3 v = v_pic;
#else
    if (alone > 0.0) delta += alone * lone_correction(g, v_own);
    float r = sim.flip_ratio;
    vec3 v = (1.0 - r) * v_pic + r * (v_own + delta);
#endif
    uint flags = 0u;
    float speed;
    limit_velocity(v, flags, speed);
    publish_status(speed, flags);
    vel[i] = vec4(v, 0.0);
}
