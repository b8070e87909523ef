// Bit-for-bit comparison of two simulations' results, for the kernel and threading tests.
#pragma once

#include "physics/stepping/simulation.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace pl::test {

inline bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

template <class T>
::testing::AssertionResult same_array(const char* name, const StateArray<T>& a, const StateArray<T>& b) {
    if (a.size() != b.size()) return ::testing::AssertionFailure() << name << ": sizes differ";
    for (std::size_t i = 0; i < a.size(); ++i) {
        bool same;
        if constexpr (std::is_same_v<T, double>) same = same_bits(a[i], b[i]);
        else same = a[i] == b[i];
        if (!same)
            return ::testing::AssertionFailure() << name << "[" << i << "]: " << +a[i] << " vs " << +b[i];
    }
    return ::testing::AssertionSuccess();
}

inline ::testing::AssertionResult same_events(const std::vector<Event>& a, const std::vector<Event>& b) {
    if (a.size() != b.size()) return ::testing::AssertionFailure() << "event counts " << a.size() << " vs " << b.size();
    for (std::size_t i = 0; i < a.size(); ++i) {
        const Event &x = a[i], &y = b[i];
        if (!same_bits(x.t, y.t) || x.particle != y.particle || x.wall != y.wall || x.kind != y.kind ||
            !same_bits(x.speed_in, y.speed_in) || !same_bits(x.speed_out, y.speed_out))
            return ::testing::AssertionFailure() << "event " << i << " differs (particle " << x.particle << " vs "
                                                 << y.particle << ", t " << x.t << " vs " << y.t << ")";
    }
    return ::testing::AssertionSuccess();
}

// Everything a step produces, compared bit for bit (force counts too, except which kernel
// phase finished the particle-steps).
inline void expect_identical(const Simulation& fast, const Simulation& generic) {
    const ParticleState &a = fast.state(), &b = generic.state();
    EXPECT_TRUE(same_array("x", a.x, b.x));
    EXPECT_TRUE(same_array("y", a.y, b.y));
    EXPECT_TRUE(same_array("z", a.z, b.z));
    EXPECT_TRUE(same_array("vx", a.vx, b.vx));
    EXPECT_TRUE(same_array("vy", a.vy, b.vy));
    EXPECT_TRUE(same_array("vz", a.vz, b.vz));
    EXPECT_TRUE(same_array("resting", a.resting, b.resting));
    EXPECT_TRUE(same_array("frozen", a.frozen, b.frozen));
    EXPECT_TRUE(same_array("dissipated_bounce", a.dissipated_bounce, b.dissipated_bounce));
    EXPECT_TRUE(same_array("dissipated_friction", a.dissipated_friction, b.dissipated_friction));
    EXPECT_TRUE(same_array("dissipated_drag", a.dissipated_drag, b.dissipated_drag));
    EXPECT_TRUE(same_array("wind_work", a.wind_work, b.wind_work));
    EXPECT_TRUE(same_events(fast.events(), generic.events()));
    ASSERT_EQ(fast.warnings().size(), generic.warnings().size());
    for (std::size_t i = 0; i < fast.warnings().size(); ++i) {
        EXPECT_EQ(fast.warnings()[i].kind, generic.warnings()[i].kind);
        EXPECT_EQ(fast.warnings()[i].particle, generic.warnings()[i].particle);
        EXPECT_EQ(fast.warnings()[i].t, generic.warnings()[i].t);
        EXPECT_EQ(fast.warnings()[i].value, generic.warnings()[i].value);
    }
    // The monitor's statistics (its scan is split over the threads like the kernel).
    EXPECT_EQ(fast.max_drag_stiffness(), generic.max_drag_stiffness());
    EXPECT_EQ(fast.observed_reynolds().lo, generic.observed_reynolds().lo);
    EXPECT_EQ(fast.observed_reynolds().hi, generic.observed_reynolds().hi);
    const ForceCounters &c = fast.counters(), &d = generic.counters();
    EXPECT_EQ(c.gravity, d.gravity);
    EXPECT_EQ(c.drag, d.drag);
    EXPECT_EQ(c.wind, d.wind);
    EXPECT_EQ(c.accepted_steps, d.accepted_steps);
    EXPECT_EQ(c.rejected_steps, d.rejected_steps);
    EXPECT_EQ(c.contacts, d.contacts);
}

}  // namespace pl::test
