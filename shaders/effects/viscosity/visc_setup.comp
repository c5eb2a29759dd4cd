// Viscosity (PF_FEATURE_VISCOSITY), first pass of a substep's solve, per face: its mass weight
// and the inverse of its diagonal in the solve's matrix (0 for a face that is not solved for:
// the Jacobi preconditioner and the mask of the unknowns in one), from the cell kinds
// (shaders/effects/viscosity/viscosity.glsl). Invocation 0 also resets the solve's state and
// restores its indirect records to their full size.
#include "common/sim.glsl"
layout(local_size_x = PF_WORKGROUP_SIZE) in;
layout(std430, binding = PF_SLOT_CELL_TYPE) readonly buffer CellType { uint cell_type[]; };
layout(std430, binding = PF_SLOT_VISC_COEF) writeonly buffer Coef { vec2 coef[]; };
layout(std430, binding = PF_SLOT_VISC_STATE) buffer State { uint state[]; };
#include "effects/viscosity/viscosity.glsl"
layout(location = PF_LOC_VISC_RECORDS) uniform ivec4 u_records;
layout(location = PF_LOC_VISC_FIRST) uniform uint u_first;

void main() {
    int id = int(flat_id());
    if (id == 0) {
        for (uint w = 0u; w < uint(PF_VISC_FACE_RECORD); ++w) {
            if (w != uint(PF_VISC_MAX_ITERATIONS) && w != uint(PF_VISC_MAX_RESIDUAL)) state[w] = 0u;
        }
        if (u_first != 0u) {
            state[PF_VISC_MAX_ITERATIONS] = 0u;
            state[PF_VISC_MAX_RESIDUAL] = 0u;
        }
        state[PF_VISC_PREV_MAX_RESIDUAL] = state[PF_VISC_MAX_RESIDUAL];
        state[PF_VISC_FACE_RECORD] = uint(u_records.x);
        state[PF_VISC_FACE_RECORD + 1] = uint(u_records.y);
        state[PF_VISC_FACE_RECORD + 2] = 1u;
        state[PF_VISC_NODE_RECORD] = uint(u_records.z);
        state[PF_VISC_NODE_RECORD + 1] = uint(u_records.w);
        state[PF_VISC_NODE_RECORD + 2] = 1u;
    }
    if (id >= face_total()) return;
    int axis;
    ivec3 f;
    decode_face(id, axis, f);
    if (visc_face_role(axis, f) != VISC_UNKNOWN) {
        coef[id] = vec2(0.0);
        return;
    }
    ivec3 ea = visc_unit(axis);
    float c = visc_coupling();
    float mass = visc_face_mass(axis, f);
    float diag = mass + c * (visc_cell_weight(f - ea) + visc_cell_weight(f));
    for (int b = 0; b < 3; ++b) {
        if (b == axis) continue;
        ivec3 eb = visc_unit(b);
        int lo = min(axis, b), hi = max(axis, b);
        diag += 0.5 * c * (visc_edge_weight(lo, hi, f) + visc_edge_weight(lo, hi, f + eb));
    }
    coef[id] = vec2(mass, 1.0 / diag);
}
