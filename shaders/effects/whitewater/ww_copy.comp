// Whitewater (PF_FEATURE_WHITEWATER), last pass, per live particle (an indirect dispatch of
// ww_commit.comp's record): this step's compacted particles back from the scratch pair into the
// buffers that engines and the render layer read (pf_get_whitewater_buffers), so those keep their
// names; only the live slots are copied.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_WW_IN_POS) writeonly buffer Pos { vec4 pos[]; };
layout(std430, binding = PF_SLOT_WW_IN_VEL) writeonly buffer Vel { vec4 vel[]; };
layout(std430, binding = PF_SLOT_WW_OUT_POS) readonly buffer OutPos { vec4 out_pos[]; };
layout(std430, binding = PF_SLOT_WW_OUT_VEL) readonly buffer OutVel { vec4 out_vel[]; };
layout(std430, binding = PF_SLOT_WW_STATE) readonly buffer State { uint state[]; };

void main() {
    uint i = flat_id();
    if (i >= state[PF_WW_LIVE]) return;
    pos[i] = out_pos[i];
    vel[i] = out_vel[i];
}
