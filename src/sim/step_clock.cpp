#include "sim/step_clock.h"

#include <algorithm>
#include <cmath>

namespace pf {

ProjectionCount projections_for(const ProjectionDemand& d) {
    double fewest = 1.0;
    if (d.longest_dt > 0.0f) fewest = std::max(fewest, std::ceil(double(d.frame_dt) / double(d.longest_dt)));
    const float v_est = std::max(d.speed + d.acceleration * d.frame_dt, d.imposed_speed);
    const double wanted =
        std::max(fewest, std::ceil(double(d.frame_dt) * v_est / (double(d.cfl) * d.cell_size)));
    ProjectionCount out;
    out.count = uint32_t(std::max(1.0, std::min(wanted, double(d.max_projections))));
    out.clamped = wanted > double(d.max_projections);
    out.travel_cells = float(double(d.frame_dt) / out.count * v_est / d.cell_size);
    return out;
}

uint32_t extrapolation_layers(const pf_sim_params& params, float travel_cells) {
    // A thousandth of a cell of slack: a travel of one cell that rounding put above 1 needs no layer.
    const double beyond_first = std::ceil(double(travel_cells) - 1e-3) - 1.0;
    return params.extrapolation_layers + uint32_t(std::clamp(beyond_first, 0.0, 16.0));
}

}  // namespace pf
