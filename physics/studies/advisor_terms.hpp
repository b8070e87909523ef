// The advisor's term table: one row per term it judges. A row says how to build, from the
// variant as configured, the two models whose runs are compared:
//   toggle rows:      measured = the term on, baseline = the term off; the difference on - off is
//                     the term's effect, whether the variant has the term on or not ("buoyancy is
//                     off but would change landing time by ...: turn it on");
//   alternative rows: measured = a cheaper drag model, baseline = the reference (sphere_re with
//                     the variant's settings); the difference says whether the cheaper model is enough.
// Each builder edits a copy of the variant's Model and returns whether it changed anything: the
// advisor runs each distinct model once (a builder that changes nothing reuses the variant's own
// run; the same builder in two rows reuses its run).
//
// Adding a term is one row in term_table() (advisor_terms.cpp): a name, whether the variant has
// it, the builders of the measured and the baseline model, and optionally why it cannot be judged
// and an extra clause for its verdict (see the buoyancy and added-mass rows).
// A row can also write its whole verdict (see the collisions row).
// Toggle verdicts read "<name> matters: ...", "<name> is off but would change ...: turn it on".
#pragma once

#include "physics/studies/advisor.hpp"

#include <span>
#include <utility>

namespace pl {

enum class TermKind { toggle, alternative };

// Sets `field` to `to`; true when that changed it. Builders are one call of this.
template <class T>
bool set(T& field, const T& to) {
    return std::exchange(field, to) != to;
}

// What a row's note (an extra clause in its verdict) may look at.
struct TermContext {
    const Model& variant;
    const VariantAdvice& advice;  // the dimensionless numbers (Re, drag/weight, density ratios)
    const ModelRun& run;          // this row's comparison
    // The measured differences in words: the metrics beyond tolerance, or "nothing beyond
    // tolerance (largest: ...)".
    const std::string& measured;
};

struct TermRow {
    const char* name;                      // in the verdicts and the JSON's "term"
    TermKind kind;
    bool (*in_scene)(const Model& variant);  // the variant has the term on / uses this model
    bool (*measured)(Model&);              // builds the measured model from a copy of the variant
    bool (*baseline)(Model&);              // builds the baseline model from a copy of the variant
    // nullptr, or a function returning why the term cannot be judged here (nullptr: it can).
    // `particles`: how many the runs follow.
    const char* (*not_applicable)(const Model& variant, std::size_t particles);
    // nullptr, or an extra clause for the verdict ("max drag/weight = 0.4").
    std::string (*note)(const TermContext&);
    // false: the row is data only (the JSON's runs), its verdict is another row's (no drag: the
    // drag toggle) or there is none (the reference against itself).
    bool verdict = true;
    // nullptr, or the whole verdict in place of the toggle's words (collisions: the estimate
    // recommends, the runs measure).
    std::string (*own_verdict)(const TermContext&) = nullptr;
};

// The reference the alternative rows compare against: sphere_re, the variant's own settings if it
// uses sphere_re.
inline constexpr DragModel reference_drag = DragModel::sphere_re;

// The candidate drag settings for `model`: the variant's own settings for its own model,
// defaults otherwise (Stokes from the air's viscosity for linear; the configured Cd for quadratic).
DragSettings candidate_drag(DragModel model, const DragSettings& configured);

// The builder that switches a copy of the variant to the reference drag model.
bool use_reference_drag(Model& m);

std::span<const TermRow> term_table();

// The collisions row's name: the advisor finds its run to size the collision estimate's duration.
inline constexpr const char* collisions_term = "collisions";

}  // namespace pl
