/* Words of the viscosity solve's state buffer (src/sim/effects/viscosity/viscosity.cpp and the
 * kernels in this folder): its own, so the viscosity never writes the pressure solver's state or
 * status. One uint array; floats stored as their bits. Scalars live on the GPU so convergence is
 * decided there: the kernel that finds it zeroes the indirect records, and every later pass of
 * that solve dispatches nothing. Valid C and GLSL: only #define lines. */
#ifndef PF_VISCOSITY_STATE_H
#define PF_VISCOSITY_STATE_H

#define PF_VISC_RZ 0          /* float: r.z of the current iterate (z = r / diag) */
#define PF_VISC_RR0 1         /* float: r.r at the start of the solve */
#define PF_VISC_ALPHA 2       /* float: CG step length */
#define PF_VISC_BETA 3        /* float: CG direction update */
#define PF_VISC_ITERATIONS 4  /* uint: iterations done in this solve */
#define PF_VISC_CONVERGED 5   /* uint: 1 once the tolerance is met (or the search breaks down) */
#define PF_VISC_ARRIVALS 6    /* uint: workgroups of the current reduction pass that have finished */
#define PF_VISC_RESIDUAL 7    /* float: |r| / |r0| after the newest iteration */
#define PF_VISC_MAX_ITERATIONS 8 /* uint: most iterations of a substep's solve in this step */
#define PF_VISC_MAX_RESIDUAL 9   /* float: largest final residual of a substep's solve in this step */
#define PF_VISC_PREV_MAX_RESIDUAL 10 /* float: MAX_RESIDUAL before the current solve */
#define PF_VISC_FACE_RECORD 12   /* indirect record (x, y, 1) over the faces */
#define PF_VISC_NODE_RECORD 16   /* indirect record (x, y, 1) over the nodes (cell corners) */
#define PF_VISC_WORDS 20

/* explicit uniform locations of the viscosity kernels */
#define PF_LOC_VISC_NU 0         /* float: kinematic viscosity, m^2/s */
#define PF_LOC_VISC_FREE_SLIP 1  /* uint: 1 = no shear stress at walls and obstacles */
#define PF_LOC_VISC_RECORDS 2    /* ivec4: workgroups (x, y) over the faces, then over the nodes */
#define PF_LOC_VISC_TOLERANCE 3  /* float: relative residual to reach */
#define PF_LOC_VISC_FIRST 4      /* uint: 1 in the first substep of a step (resets the step's maxima) */

#endif
