// One layer of velocity extrapolation: an invalid face with valid neighbours in its own
// lattice takes their average and becomes valid. Reads the old mask, writes the new one;
// it writes only faces the old mask calls invalid and reads only valid ones, so updating
// the velocity in place is race free.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_FACE_VEL) buffer FaceVel { float face_vel[]; };
layout(std430, binding = PF_SLOT_FACE_VALID) readonly buffer Valid { uint valid_in[]; };
layout(std430, binding = PF_SLOT_FACE_VALID_OUT) writeonly buffer ValidOut { uint valid_out[]; };

void main() {
    int id = int(flat_id());
    if (id >= face_total()) return;
    if (valid_in[id] != 0u) {
        valid_out[id] = 1u;
        return;
    }
    int axis;
    ivec3 f;
    decode_face(id, axis, f);
    vec3 pair_sum = vec3(0.0);  // per axis pair first: mirror-exact (see mirror_sum)
    float count = 0.0;
    for (int n = 0; n < 6; ++n) {
        ivec3 nb = f + kNeighbours[n];
        if (!face_inside(axis, nb)) continue;
        int nid = face_index(axis, nb);
        if (valid_in[nid] != 0u) {
            pair_sum[n / 2] += face_vel[nid];
            count += 1.0;
        }
    }
    float sum = (pair_sum.x + pair_sum.y) + pair_sum.z;
    if (count > 0.0) face_vel[id] = sum / count;
    valid_out[id] = count > 0.0 ? 1u : 0u;
}
