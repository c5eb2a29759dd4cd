/* Explicit uniform locations of the Jacobi kernel, shared with src/sim/solvers/jacobi. */
#ifndef PF_JACOBI_LOCATIONS_H
#define PF_JACOBI_LOCATIONS_H
#define PF_LOC_JACOBI_OMEGA 0
#endif
