#include "physics/studies/expectations.hpp"

#include <cmath>

namespace pl {

std::optional<double> metric_value(const ParticleMetrics& p, Quantity q) {
    switch (q) {
        case Quantity::time_of_flight_s: return p.first_impact_time;
        case Quantity::range_at_first_impact_m: return p.range_at_first_impact;
        case Quantity::apex_height_m: return p.apex_height;
        case Quantity::apex_time_s: return p.apex_time;
        case Quantity::final_range_m: return p.final_range;
        case Quantity::bounces: return static_cast<double>(p.bounces);
        case Quantity::time_to_rest_s: return p.time_to_rest;
        case Quantity::lost_to_drag_J: return p.lost_drag;
        case Quantity::lost_to_bounces_J: return p.lost_bounce;
        case Quantity::lost_to_friction_J: return p.lost_friction;
        case Quantity::wind_work_J: return p.wind_work;
    }
    return std::nullopt;
}

std::vector<ExpectationResult> check_expectations(const std::vector<Expectation>& expect,
                                                  const std::vector<VariantMetrics>& variants) {
    std::vector<ExpectationResult> out;
    out.reserve(expect.size());
    for (const Expectation& e : expect) {
        ExpectationResult r{e, std::nullopt, false};
        if (e.variant < variants.size() && e.particle < variants[e.variant].particles.size())
            r.measured = metric_value(variants[e.variant].particles[e.particle], e.quantity);
        r.met = r.measured && std::abs(*r.measured - e.value) <= e.tolerance;
        out.push_back(r);
    }
    return out;
}

}  // namespace pl
