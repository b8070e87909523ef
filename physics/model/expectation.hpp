// What a preset says is worth watching: a compare metric of one particle of one variant, its
// expected value and tolerance ("rest at 1.36 s +- 0.01"). The quantities are the compare
// metrics (physics/studies/metrics.hpp measures them, metric_value reads one); their names
// here are the only list, the ones `particle-lab compare --json` prints.
#pragma once

#include <cstdint>

namespace pl {

enum class Quantity {
    time_of_flight_s,
    range_at_first_impact_m,
    apex_height_m,
    apex_time_s,
    final_range_m,
    bounces,
    time_to_rest_s,
    lost_to_drag_J,
    lost_to_bounces_J,
    lost_to_friction_J,
    wind_work_J,
};

struct QuantityInfo {
    Quantity quantity;
    const char* name;  // the key in `compare --json` and in a preset's "expect"
    const char* unit;  // SI, "" for a count
};

inline constexpr QuantityInfo quantity_table[] = {
    {Quantity::time_of_flight_s, "time_of_flight_s", "s"},
    {Quantity::range_at_first_impact_m, "range_at_first_impact_m", "m"},
    {Quantity::apex_height_m, "apex_height_m", "m"},
    {Quantity::apex_time_s, "apex_time_s", "s"},
    {Quantity::final_range_m, "final_range_m", "m"},
    {Quantity::bounces, "bounces", ""},
    {Quantity::time_to_rest_s, "time_to_rest_s", "s"},
    {Quantity::lost_to_drag_J, "lost_to_drag_J", "J"},
    {Quantity::lost_to_bounces_J, "lost_to_bounces_J", "J"},
    {Quantity::lost_to_friction_J, "lost_to_friction_J", "J"},
    {Quantity::wind_work_J, "wind_work_J", "J"},
};
inline constexpr int quantity_count = static_cast<int>(sizeof(quantity_table) / sizeof(quantity_table[0]));

constexpr const QuantityInfo& quantity_info(Quantity q) { return quantity_table[static_cast<int>(q)]; }
constexpr const char* to_string(Quantity q) { return quantity_info(q).name; }

// The table is indexed by the enumeration: its rows must stay in the enumeration's order.
constexpr bool quantity_table_in_order() {
    for (int i = 0; i < quantity_count; ++i)
        if (static_cast<int>(quantity_table[i].quantity) != i) return false;
    return true;
}
static_assert(quantity_table_in_order(), "quantity_table rows must follow enum Quantity");

struct Expectation {
    Quantity quantity = Quantity::time_to_rest_s;
    double value = 0.0;
    double tolerance = 0.0;      // met when |measured - value| <= tolerance
    std::uint64_t particle = 0;  // index into the scene's particles (the listed ones, then the emitted)
    std::uint64_t variant = 0;   // index into the variants (0: the scene itself when it has none)
};

}  // namespace pl
