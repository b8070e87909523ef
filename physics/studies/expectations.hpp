// A preset's expectations (physics/model/expectation.hpp) held against what was measured: the
// compare metrics of the named particle and variant.
#pragma once

#include "physics/model/expectation.hpp"
#include "physics/studies/metrics.hpp"

#include <optional>
#include <vector>

namespace pl {

// One compare metric of a particle; empty when it has no value (never landed, never at rest).
std::optional<double> metric_value(const ParticleMetrics& p, Quantity q);

struct ExpectationResult {
    Expectation expected;
    std::optional<double> measured;  // empty: not measured (no such variant or particle) or no value yet
    bool met = false;                // measured and |measured - value| <= tolerance
};

// Each expectation against `variants` (one VariantMetrics per variant, in the scene's order).
std::vector<ExpectationResult> check_expectations(const std::vector<Expectation>& expect,
                                                  const std::vector<VariantMetrics>& variants);

}  // namespace pl
