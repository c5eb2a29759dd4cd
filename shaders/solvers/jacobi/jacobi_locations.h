/* Explicit uniform locations of the Jacobi kernel, shared with src/sim/solvers/jacobi. */
#ifndef PF_JACOBI_LOCATIONS_H
#define PF_JACOBI_LOCATIONS_H
#include "solvers/common/solver_state.h"
#define PF_LOC_JACOBI_OMEGA PF_LOC_SOLVER_OMEGA
#endif
