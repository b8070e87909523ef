// A preset's expectations held against measured metrics: met within the tolerance, not met
// outside it, and not measured when the metric has no value or the particle does not exist.
#include "physics/studies/expectations.hpp"

#include <gtest/gtest.h>

namespace pl {
namespace {

VariantMetrics one_particle(std::optional<double> time_to_rest, double apex) {
    VariantMetrics v;
    ParticleMetrics p;
    p.time_to_rest = time_to_rest;
    p.apex_height = apex;
    p.bounces = 7;
    v.particles.push_back(p);
    return v;
}

TEST(Expectations, MetWithinToleranceOnly) {
    const std::vector<Expectation> expect = {{Quantity::time_to_rest_s, 1.36, 0.01, 0, 0},
                                             {Quantity::apex_height_m, 2.0, 0.05, 0, 0},
                                             {Quantity::bounces, 7.0, 0.0, 0, 0}};
    const auto r = check_expectations(expect, {one_particle(1.355, 2.1)});
    ASSERT_EQ(r.size(), 3u);
    EXPECT_TRUE(r[0].met);
    EXPECT_DOUBLE_EQ(*r[0].measured, 1.355);
    EXPECT_FALSE(r[1].met);  // 0.1 off, tolerance 0.05
    EXPECT_DOUBLE_EQ(*r[1].measured, 2.1);
    EXPECT_TRUE(r[2].met);   // a count, exactly
}

TEST(Expectations, NotMeasuredIsNotMet) {
    const std::vector<Expectation> expect = {{Quantity::time_to_rest_s, 1.36, 0.01, 0, 0},   // never at rest
                                             {Quantity::apex_height_m, 2.0, 0.05, 3, 0},     // no particle 3
                                             {Quantity::apex_height_m, 2.0, 0.05, 0, 1}};    // no variant 1
    const auto r = check_expectations(expect, {one_particle(std::nullopt, 2.0)});
    for (const ExpectationResult& x : r) {
        EXPECT_FALSE(x.measured);
        EXPECT_FALSE(x.met);
    }
}

TEST(Expectations, EveryQuantityIsReadAndNamedOnce) {
    ParticleMetrics p;
    p.first_impact_time = 0.5;
    p.range_at_first_impact = 1.5;
    p.time_to_rest = 2.5;
    for (int i = 0; i < quantity_count; ++i) {
        const Quantity q = static_cast<Quantity>(i);
        EXPECT_TRUE(metric_value(p, q).has_value()) << to_string(q);
        for (int k = 0; k < i; ++k) EXPECT_STRNE(to_string(q), quantity_table[k].name);
    }
}

}  // namespace
}  // namespace pl
