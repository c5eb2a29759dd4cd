// Which particle slot invocation t of a particle kernel works on. With PF_ORDERED 1 the kernel
// walks the live slots in the order the tiled P2G grouped them by tile this substep, so
// neighbouring invocations read neighbouring grid faces (coherent cache lines instead of
// particles scattered over the domain); each particle's result is the same either way.
#ifndef PF_ORDERED
#define PF_ORDERED 0
#endif
#if PF_ORDERED
layout(std430, binding = PF_SLOT_PARTICLE_ORDER) readonly buffer ParticleOrder { uint particle_order[]; };
uint particle_slot(uint t) { return particle_order[t]; }
#else
uint particle_slot(uint t) { return t; }
#endif
