#include "sim/step_clock.h"

#include <algorithm>
#include <cmath>

namespace pf {

ProjectionCount projections_for(const ProjectionDemand& d) {
    double fewest = 1.0;
    if (d.max_dt > 0.0f) fewest = std::max(fewest, std::ceil(double(d.frame_dt) / double(d.max_dt)));
    if (d.strain > 0.0f) {
        const double unit = d.gravity > 0.0f ? std::sqrt(double(d.cell_size) / d.gravity) : double(kStrainGravityTime);
        fewest = std::max(fewest, std::ceil(double(d.frame_dt) * d.strain / kStrainRate * unit / kStrainGravityTime));
    }
    // A frame a rounding longer than the longest projection takes one.
    const float longest = longest_projection_seconds(d.longest_projection, d.cell_size, d.gravity);
    if (longest > 0.0f) fewest = std::max(fewest, std::ceil(double(d.frame_dt) / double(longest) - 1e-4));
    const float v_est = std::max(d.speed + d.acceleration * d.frame_dt, d.imposed_speed);
    const double wanted =
        std::max(fewest, std::ceil(double(d.frame_dt) * v_est / (double(d.cfl) * d.cell_size)));
    ProjectionCount out;
    out.count = uint32_t(std::max(1.0, std::min(wanted, double(d.max_projections))));
    out.clamped = wanted > double(d.max_projections);
    out.travel_cells = float(double(d.frame_dt) / out.count * v_est / d.cell_size);
    return out;
}

float longest_projection_seconds(float units, float cell_size, float gravity) {
    if (!(units > 0.0f) || !(gravity > 0.0f) || !(cell_size > 0.0f)) return 0.0f;
    return units * std::sqrt(cell_size / gravity);
}

BudgetPlan fit_budget(float budget_ms, uint32_t wanted, uint32_t max_iterations, const MeasuredStep& m) {
    BudgetPlan plan;
    plan.projections = wanted;
    plan.iteration_cap = max_iterations;
    if (!(budget_ms > 0.0f) || m.step == 0 || m.projections == 0 || !(m.total_ms > 0.0f)) return plan;
    const double per_projection = double(m.total_ms) / m.projections;
    const double fit = std::floor(double(budget_ms) / per_projection);
    if (double(wanted) <= fit) return plan;
    plan.projections = uint32_t(std::max(1.0, fit));
    plan.fewer_projections = plan.projections < wanted;
    if (fit >= 1.0 || m.iterations == 0 || !(m.solve_ms > 0.0f)) return plan;
    // One projection is over the budget: the solve gives up what the rest of it leaves.
    const double solve = double(m.solve_ms) / m.projections, per_iteration = solve / m.iterations;
    const double rest = per_projection - solve;
    const double allowed = std::floor((double(budget_ms) - rest) / per_iteration);
    plan.iteration_cap = uint32_t(std::clamp(allowed, 1.0, double(max_iterations)));
    return plan;
}

uint32_t extrapolation_layers(const pf_sim_params& params, float travel_cells) {
    // A thousandth of a cell of slack: a travel of one cell that rounding put above 1 needs no layer.
    const double beyond_first = std::ceil(double(travel_cells) - 1e-3) - 1.0;
    return params.extrapolation_layers + uint32_t(std::clamp(beyond_first, 0.0, 16.0));
}

}  // namespace pf
