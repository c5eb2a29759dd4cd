/* The public header must compile as C99 and its defaults must be callable from C. */
#include "pf/pf.h"

int pf_test_c_header_defaults_ok(void);

int pf_test_c_header_defaults_ok(void) {
    pf_sim_desc desc = pf_default_sim_desc();
    pf_sim_params params = pf_default_sim_params();
    pf_stats stats = {0};
    pf_gl_buffers buffers = {0};
    pf_force_field field = pf_default_force_field();
    pf_obstacle obstacle = pf_default_obstacle();
    (void)stats;
    (void)buffers;
    desc.features = PF_FEATURE_ALL;
    return field.radius > 0.0f && obstacle.half_extents[0] > 0.0f && desc.grid_size[0] > 0 && params.pressure_iterations > 0 && pf_version() == PF_VERSION &&
           pf_result_string(PF_OK) != 0;
}

/* A C caller may pass any bits where the API takes an enum (C converts them; a C++ program may not
 * even load a value beyond the enum's range, which UBSan reports): the library must refuse them. */
pf_result pf_test_c_set_gpu_timing_bits(pf_sim* sim, unsigned bits);

pf_result pf_test_c_set_gpu_timing_bits(pf_sim* sim, unsigned bits) { return pf_set_gpu_timing(sim, (pf_gpu_timing)bits); }
