#include "io/metrics_json.hpp"

namespace pl::cli {

using Json = nlohmann::ordered_json;

Json json_document() {
    Json j;
    j["schema_version"] = json_schema_version;
    return j;
}

Json optional_json(const std::optional<double>& v) { return v ? Json(*v) : Json(nullptr); }

Json particle_metrics_json(const ParticleMetrics& p) {
    Json j;
    j["time_of_flight_s"] = optional_json(p.first_impact_time);
    j["first_impact_wall"] = p.first_impact_wall >= 0 ? Json(wall_name(p.first_impact_wall)) : Json(nullptr);
    j["range_at_first_impact_m"] = optional_json(p.range_at_first_impact);
    j["apex_height_m"] = p.apex_height;
    j["apex_time_s"] = p.apex_time;
    j["final_range_m"] = p.final_range;
    j["bounces"] = p.bounces;
    j["time_to_rest_s"] = optional_json(p.time_to_rest);
    j["lost_to_drag_J"] = p.lost_drag;
    j["lost_to_bounces_J"] = p.lost_bounce;
    j["lost_to_friction_J"] = p.lost_friction;
    j["wind_work_J"] = p.wind_work;
    return j;
}

}  // namespace pl::cli
