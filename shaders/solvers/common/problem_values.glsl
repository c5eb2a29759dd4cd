// A solve's iterate and right-hand side (less the singular mean) at a cell, as the kernel's value
// type (solver_value.glsl): a pair kernel (PF_PAIR 1) reads the second problem's from x_second
// and rhs_second. Requires `x`, `rhs` (and those) and state.glsl before including this file.
#if PF_PAIR
vec2 x_at(int c) { return vec2(x[c], x_second[c]); }
vec2 b_at(int c) { return vec2(rhs[c], rhs_second[c]) - state_value(PF_SOLVER_B_MEAN); }
#else
float x_at(int c) { return x[c]; }
float b_at(int c) { return rhs[c] - rhs_mean(); }
#endif
