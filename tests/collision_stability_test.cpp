// The stability study's collision slice (physics/studies/collision_stability.cpp) and the
// crossing warning it brought to light (physics/collide/pair_crossings.hpp): a pair that goes
// through each other in one long step is reported, by the study and by the engine.
#include "physics/stepping/simulation.hpp"
#include "physics/stepping/warnings.hpp"
#include "physics/studies/stability_study.hpp"
#include "test_scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace pl {
namespace {

StabilityCase pair_case(Method method, double dt, double speed, double e, double radii, double masses) {
    StabilityCase c;
    c.method = method;
    c.dt = dt;
    c.speed = speed;
    c.restitution = e;
    c.radius_fraction = 0.01;
    c.pair_radius_ratio = radii;
    c.pair_mass_ratio = masses;
    return c;
}

bool warned(const Simulation& sim, WarningKind kind) {
    return std::any_of(sim.warnings().begin(), sim.warnings().end(), [kind](const Warning& w) { return w.kind == kind; });
}

// Two equal balls 0.6 m apart at 100 m/s with dt = 0.05 s: each crosses the 2 m room in the step
// and stops on the far wall (e = 0), past the other. The pass never met them (it meets pairs on
// their chords, and each chord ended at a wall); before the crossing check nothing said so.
TEST(CollisionCrossing, APairThatSwapsSidesInOneStepIsWarned) {
    for (const Method method : {Method::semi_implicit_euler, Method::velocity_verlet}) {
        SCOPED_TRACE(to_string(method));
        Simulation sim(test::colliding_room(0.05, method, 0.0, 0.3, 0.3),
                       {{{-0.3, 1.0, 0.0}, {100.0, 0.0, 0.0}, 0.05, 0.02}, {{0.3, 1.0, 0.0}, {-100.0, 0.0, 0.0}, 0.05, 0.02}});
        sim.step();
        const bool swapped = sim.state().x[0] > sim.state().x[1];
        if (swapped) {
            EXPECT_TRUE(warned(sim, WarningKind::collision_crossing)) << "went through each other unwarned";
            const auto w = std::find_if(sim.warnings().begin(), sim.warnings().end(),
                                        [](const Warning& x) { return x.kind == WarningKind::collision_crossing; });
            ASSERT_NE(w, sim.warnings().end());
            EXPECT_GT(w->value, 1.0);  // the separation moved more than a contact distance
            EXPECT_NE(warning_message(*w, sim.model()).find("crossed"), std::string::npos);
        }
    }
}

// The same pair at a step the pass can follow meets, and nothing is reported.
TEST(CollisionCrossing, NoWarningWhereTheStepIsShortEnough) {
    for (const double dt : {1e-3, 1e-4}) {
        Simulation sim(test::colliding_room(dt, Method::semi_implicit_euler, 0.5, 0.3, 0.3),
                       {{{-0.3, 1.0, 0.0}, {10.0, 3.0, 0.0}, 0.05, 0.02}, {{0.3, 1.0, 0.0}, {-10.0, 3.0, 0.0}, 0.05, 0.02}});
        while (sim.time() < 0.5) sim.step();
        EXPECT_FALSE(warned(sim, WarningKind::collision_crossing)) << "dt " << dt;
        EXPECT_FALSE(warned(sim, WarningKind::collision_overlap)) << "dt " << dt;
    }
}

TEST(CollisionStability, APairThatMeetsIsStableAndOneThatSwapsIsTunnelledAndWarned) {
    const StabilityBase base = default_stability_base();
    const StabilityCell calm = classify_stability(base, pair_case(Method::velocity_verlet, 1e-3, 10.0, 0.5, 1.0, 1.0));
    EXPECT_EQ(calm.outcome, StabilityOutcome::stable) << calm.detail;
    EXPECT_LT(calm.max_overlap, 0.01);
    EXPECT_FALSE(calm.collision_warned);
    const StabilityCell swap = classify_stability(base, pair_case(Method::velocity_verlet, 0.05, 100.0, 0.0, 1.0, 1.0));
    EXPECT_EQ(swap.outcome, StabilityOutcome::tunnelled) << swap.detail;
    EXPECT_TRUE(swap.collision_warned);
}

// Every cell of the quick collision slice that ends badly was warned of by the engine: the study
// finds no failure the user was not told of (energy growth aside: it is the method's, explicit
// Euler's and at dt = 0.05 s semi-implicit Euler's, as in the single-particle cells).
TEST(CollisionStability, EveryDeepOrCrossedCellOfTheQuickSliceWasWarned) {
    StabilityOptions o;
    o.grid = default_stability_grid(true);
    o.grid.dts.clear();  // the collision slice alone
    o.grid.sweep_dts.clear();
    const StabilityReport r = run_stability_study(default_stability_base(), o);
    ASSERT_EQ(r.pair_cells.size(), o.grid.methods.size() * 32);
    std::size_t stable = 0;
    for (const StabilityCell& c : r.pair_cells) {
        stable += c.outcome == StabilityOutcome::stable;
        EXPECT_NE(c.outcome, StabilityOutcome::nan) << c.detail;
        EXPECT_NE(c.outcome, StabilityOutcome::escaped) << c.detail;
        if (c.outcome == StabilityOutcome::tunnelled || c.outcome == StabilityOutcome::overlap) {
            EXPECT_TRUE(c.collision_warned) << to_string(c.c.method) << " dt " << c.c.dt << " speed " << c.c.speed << " e "
                                            << c.c.restitution << " radii 1:" << c.c.pair_radius_ratio << " masses 1:"
                                            << c.c.pair_mass_ratio << ": " << c.detail;
        }
    }
    EXPECT_GT(stable, r.pair_cells.size() / 2);
}

}  // namespace
}  // namespace pl
