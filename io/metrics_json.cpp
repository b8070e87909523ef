#include "io/metrics_json.hpp"

namespace pl::cli {

using Json = nlohmann::ordered_json;

Json json_document() {
    Json j;
    j["schema_version"] = json_schema_version;
    return j;
}

Json optional_json(const std::optional<double>& v) { return v ? Json(*v) : Json(nullptr); }

// The keys are the quantity names (physics/model/expectation.hpp), in their order, with the wall
// of the first impact after the time of flight; counts stay integers.
Json particle_metrics_json(const ParticleMetrics& p) {
    Json j;
    for (const QuantityInfo& q : quantity_table) {
        if (q.quantity == Quantity::bounces) j[q.name] = p.bounces;
        else j[q.name] = optional_json(metric_value(p, q.quantity));
        if (q.quantity == Quantity::time_of_flight_s)
            j["first_impact_wall"] = p.first_impact_wall >= 0 ? Json(wall_name(p.first_impact_wall)) : Json(nullptr);
    }
    return j;
}

Json expectations_json(const std::vector<ExpectationResult>& results) {
    Json list = Json::array();
    for (const ExpectationResult& r : results)
        list.push_back({{"quantity", to_string(r.expected.quantity)},
                        {"variant", r.expected.variant},
                        {"particle", r.expected.particle},
                        {"expected", r.expected.value},
                        {"tolerance", r.expected.tolerance},
                        {"measured", optional_json(r.measured)},
                        {"met", r.met}});
    return list;
}

}  // namespace pl::cli
