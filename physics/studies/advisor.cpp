#include "physics/studies/advisor.hpp"

#include "physics/model/air_model.hpp"
#include "physics/stepping/contact.hpp"

#include "physics/studies/advisor_runs.hpp"
#include "physics/studies/advisor_terms.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <span>
#include <string_view>

namespace pl {

namespace {

// Advice looks at the first particles only: their trajectories represent the scene, and a
// million-particle emitter would make the extra runs expensive.
constexpr std::size_t max_advice_particles = 100;

// "+0.62 s", "-7.1 mm/s", "3.1 um": three significant digits in the unit, milli- or micro-unit.
std::string quantity(double v, const char* unit, bool sign) {
    const double a = std::abs(v);
    double scale = 1.0;
    const char* prefix = "";
    if (a > 0.0 && a < 1e-4) scale = 1e6, prefix = "u";
    else if (a > 0.0 && a < 0.1) scale = 1e3, prefix = "m";
    return sign ? fmt::format("{:+.3g} {}{}", v * scale, prefix, unit) : fmt::format("{:.3g} {}{}", v * scale, prefix, unit);
}

}  // namespace

namespace {

// Each metric's words, JSON key and unit: one row per AdviceMetric, in its order.
struct MetricNames {
    AdviceMetric metric;
    const char* words;
    const char* json_key;
    const char* unit;
};
constexpr std::array<MetricNames, advice_metric_count> metric_names = {{
    {AdviceMetric::landing_time, "landing time", "landing_time_s", "s"},
    {AdviceMetric::impact_speed, "impact speed", "impact_speed_m_s", "m/s"},
    {AdviceMetric::time_to_rest, "time to rest", "time_to_rest_s", "s"},
    {AdviceMetric::range, "range", "range_m", "m"},
    {AdviceMetric::apex_height, "apex height", "apex_height_m", "m"},
    {AdviceMetric::landing_point, "landing point", "landing_point_m", "m"},
}};
static_assert([] {
    for (std::size_t i = 0; i < advice_metric_count; ++i)
        if (metric_names[i].metric != advice_metrics[i]) return false;
    return true;
}());

const MetricNames& names_of(AdviceMetric m) { return metric_names[static_cast<std::size_t>(m)]; }

}  // namespace

const char* to_string(AdviceMetric m) { return names_of(m).words; }
const char* json_key(AdviceMetric m) { return names_of(m).json_key; }
const char* unit_of(AdviceMetric m) { return names_of(m).unit; }

double AdviceTolerances::absolute(AdviceMetric m) const {
    const std::string_view unit = unit_of(m);
    return unit == "s" ? seconds : unit == "m/s" ? metres_per_second : metres;
}

double AdviceTolerances::limit(AdviceMetric m, double baseline) const {
    return std::max(absolute(m), m == AdviceMetric::landing_point ? 0.0 : relative * std::abs(baseline));
}

std::optional<double> MetricDelta::relative() const {
    if (!measured || baseline == 0.0) return std::nullopt;
    return difference / std::abs(baseline);
}

std::string describe(AdviceMetric m, const MetricDelta& d) {
    if (!d.measured) return fmt::format("{}: not reached", to_string(m));
    if (m == AdviceMetric::landing_point)
        return fmt::format("landing point moves {}{}", quantity(d.difference, "m", false),
                           d.at_least ? " (lands in one run only: to its end point)" : "");
    std::string s = fmt::format("{} {}{}", to_string(m), d.at_least ? (d.difference < 0 ? "<= " : ">= ") : "",
                                quantity(d.difference, unit_of(m), true));
    if (const std::optional<double> r = d.relative(); r && !d.at_least)
        s += std::abs(*r) >= 0.1 ? fmt::format(" ({:+.0f}%)", 100.0 * *r) : fmt::format(" ({:+.2g}%)", 100.0 * *r);
    if (d.impact > 1) s += fmt::format(" at impact {}", d.impact);
    if (d.at_least) s += m == AdviceMetric::landing_time ? " (lands in one run only)" : " (rests in one run only)";
    return s;
}

namespace {

using Builder = bool (*)(Model&);

// The distinct models the rows need, each run once: keyed by the first builder that made it, or
// by nullptr for the variant as configured (a builder that changed nothing). A builder whose
// model is one already planned gets that one's key: the reference drag and the row of the same
// drag model (or the drag toggle in a scene without drag) share one run.
struct RunPlan {
    std::map<Builder, Model> models;
    Builder key(const Model& variant, Builder b) {
        Model m = variant;
        if (!b(m)) return nullptr;
        for (const auto& [key, planned] : models)
            if (planned == m) return key;
        models.emplace(b, m);
        return b;
    }
};

// The metric of the highest score (`score(m)`: none for a metric that is no candidate), or
// `fallback` when none is.
template <class Score>
AdviceMetric highest(Score score, AdviceMetric fallback = AdviceMetric::landing_point) {
    AdviceMetric best = fallback;
    double top = -1.0;
    for (AdviceMetric m : advice_metrics)
        if (const std::optional<double> s = score(m); s && *s > top) best = m, top = *s;
    return best;
}

// The metric largest relative to its tolerance, described (for "nothing beyond tolerance
// (largest: ...)").
std::string describe_largest(const ModelRun& r, const AdviceTolerances& tol) {
    const AdviceMetric largest = highest([&](AdviceMetric m) -> std::optional<double> {
        const MetricDelta& d = r.metric(m);
        if (!d.measured) return std::nullopt;
        return std::abs(d.difference) / tol.limit(m, d.baseline);
    });
    return describe(largest, r.metric(largest));
}

// The metric beyond tolerance furthest past the nudge's difference (all are within the chaos).
AdviceMetric most_chaotic(const ModelRun& r, const ModelRun& chaos) {
    return highest([&](AdviceMetric m) -> std::optional<double> {
        if (!r.metric(m).within_chaos) return std::nullopt;
        return std::abs(r.metric(m).difference) / std::abs(chaos.metric(m).difference);
    });
}

// A metric within the chaos whose mean shift over the particles is beyond tolerance (the
// absolute one: a mean has no one baseline value for the relative) and chance.
bool systematic(AdviceMetric m, const MetricDelta& d, const AdviceTolerances& tol) {
    return m != AdviceMetric::landing_point && d.samples >= systematic_samples && std::abs(d.mean) > tol.absolute(m) &&
           std::abs(d.mean) > systematic_errors * d.standard_error;
}

// Marks a row's metrics beyond tolerance that moving the starts (by half the length tolerance)
// changes as much (up to chaos_factor times). A row whose every such metric is marked is within
// the chaos, and then matters only through a systematic mean shift.
void mark_chaos(const ModelRun& chaos, const AdviceTolerances& tol, ModelRun& r) {
    bool all = r.matters, shifted = false;
    for (AdviceMetric m : advice_metrics) {
        MetricDelta& d = r.metrics[static_cast<std::size_t>(m)];
        const MetricDelta& c = chaos.metric(m);
        if (!d.beyond_tolerance) continue;
        d.within_chaos = c.beyond_tolerance && std::abs(d.difference) <= chaos_factor * std::abs(c.difference);
        d.systematic = d.within_chaos && systematic(m, d, tol);
        all = all && d.within_chaos;
        shifted = shifted || d.systematic;
    }
    r.within_chaos = all;
    if (all) r.matters = shifted;
}

// "impact speed -0.12 m/s +- 21 mm/s over 240"
std::string mean_words(AdviceMetric m, const MetricDelta& d) {
    return fmt::format("{} {} +- {} over {}", to_string(m), quantity(d.mean, unit_of(m), true),
                       quantity(d.standard_error, unit_of(m), false), d.samples);
}

// For a row whose differences beyond tolerance are all within the scene's chaos: the nudge's
// difference, and the systematic mean shifts (or the largest mean shift, which is not).
std::string chaos_words(const ModelRun& r, const ModelRun& chaos) {
    const AdviceMetric m = most_chaotic(r, chaos);
    std::string s = fmt::format("particle by particle all within the scene's chaos (moving every start by half the length "
                                "tolerance gives {})",
                                describe(m, chaos.metric(m)));
    std::string shifts;
    for (AdviceMetric k : advice_metrics)
        if (r.metric(k).systematic) shifts += (shifts.empty() ? "" : ", ") + mean_words(k, r.metric(k));
    if (!shifts.empty()) return s + ", but on average " + shifts + ": a systematic effect";
    // The mean shift furthest from 0 in standard errors.
    const AdviceMetric largest_shift = highest(
        [&](AdviceMetric k) -> std::optional<double> {
            const MetricDelta& d = r.metric(k);
            if (k == AdviceMetric::landing_point || !d.within_chaos || !(d.standard_error > 0.0)) return std::nullopt;
            return std::abs(d.mean) / d.standard_error;
        },
        m);
    return s + fmt::format(", and no mean shift is beyond tolerance and {:g} standard errors (largest: {})", systematic_errors,
                           mean_words(largest_shift, r.metric(largest_shift)));
}

// The starts moved `distance` horizontally, diagonally in x and z, in a pattern that differs
// between neighbours in the list (a rigid shift of every start would keep the particles'
// relative positions), kept inside the room.
std::vector<ParticleSpec> nudged(const Model& model, std::vector<ParticleSpec> particles, double distance) {
    const RoomBounds room(model.room);
    const double d = distance / std::numbers::sqrt2;
    for (std::size_t k = 0; k < particles.size(); ++k) {
        const Vec3 step(k % 2 ? d : -d, 0.0, (k / 2) % 2 ? d : -d);
        particles[k].position = room.clamp_inside(particles[k].position + step, particles[k].radius);
    }
    return particles;
}

std::string beyond_list(const ModelRun& r) {
    std::string s;
    for (AdviceMetric m : advice_metrics)
        if (r.metric(m).beyond_tolerance) s += (s.empty() ? "" : ", ") + describe(m, r.metric(m));
    return s;
}

// A row beyond tolerance only by the scene's chaos, with no systematic shift: its effect, if
// any, is smaller than what the advice's particles can show. `why`: what was measured, in words.
std::string chaos_verdict(const TermRow& row, const ModelRun& r, const std::string& why) {
    if (row.kind == TermKind::alternative)
        return fmt::format("{} cannot be told from {} drag within the scene's chaos: {}: enough here", row.name,
                           to_string(reference_drag), why);
    if (r.in_scene) return fmt::format("{}: its effect cannot be told from the scene's chaos: {}: it could be turned off", row.name, why);
    return fmt::format("{} is off, and its effect cannot be told from the scene's chaos: {}", row.name, why);
}

// `measured`: measured_words of the row's run (the metrics beyond tolerance, with the scene's
// chaos where they are within it).
std::string verdict(const TermRow& row, const ModelRun& r, const std::string& measured, const std::string& note,
                    const AdviceTolerances& tol) {
    if (!r.not_applicable.empty()) return fmt::format("{}: {}", row.name, r.not_applicable);
    const std::string extra = note.empty() ? "" : "; " + note;
    if (r.within_chaos && !r.matters) return chaos_verdict(row, r, measured + extra);
    if (r.matters) {
        if (row.kind == TermKind::alternative)
            return fmt::format("{} differs from {} drag: {}{}: not enough here", row.name, to_string(reference_drag), measured, extra);
        if (r.in_scene) return fmt::format("{} matters: {}{}", row.name, measured, extra);
        return fmt::format("{} is off but would change {}{}: turn it on", row.name, measured, extra);
    }
    const std::string most = "(largest: " + describe_largest(r, tol) + ")";
    if (row.kind == TermKind::alternative)
        return fmt::format("{} is within tolerance of {} drag {}{}: enough here", row.name, to_string(reference_drag), most, extra);
    if (r.in_scene) return fmt::format("{} changes nothing beyond tolerance {}{}: it could be turned off", row.name, most, extra);
    return fmt::format("{} is off and would change nothing beyond tolerance {}{}", row.name, most, extra);
}

// What the runs measured, in words: the metrics beyond tolerance (and the scene's chaos where
// they are within it), or the largest within.
std::string measured_words(const ModelRun& r, const ModelRun& chaos, const AdviceTolerances& tol) {
    if (r.within_chaos) return beyond_list(r) + "; " + chaos_words(r, chaos);
    if (r.matters) return beyond_list(r);
    return "nothing beyond tolerance (largest: " + describe_largest(r, tol) + ")";
}

std::string row_verdict(const TermRow& row, const TermContext& c, const AdviceTolerances& tol) {
    if (row.own_verdict && c.run.not_applicable.empty()) return row.own_verdict(c);
    return verdict(row, c.run, c.measured, row.note ? row.note(c) : std::string(), tol);
}

std::size_t row_index(const char* name) {
    const std::span<const TermRow> table = term_table();
    for (std::size_t k = 0; k < table.size(); ++k)
        if (std::string_view(table[k].name) == name) return k;
    return table.size();
}

void add_warnings(const Model& model, VariantAdvice& a) {
    if (a.max_mach > 0.3)
        a.warnings.push_back(fmt::format("Mach {:.2f}: compressibility is not modelled (unreliable above Mach 0.3)", a.max_mach));
    if (model.drag.model != DragModel::none) {
        const ReRange valid = drag_validity(model.drag.model);
        if (a.re_max > 0.0 && (a.re_min < valid.lo || a.re_max > valid.hi))
            a.warnings.push_back(fmt::format("Re = {:.2g} .. {:.2g} leaves the {} model's validity range {:.3g} < Re < {:.3g}",
                                             a.re_min, a.re_max, to_string(model.drag.model), valid.lo, valid.hi));
    }
}

// rho_air / rho_particle, rho_particle = m / (4/3 pi R^3), with the air where the particle starts
// (ISA air thins with height).
std::vector<double> density_ratios(const Model& model, const std::vector<ParticleSpec>& particles) {
    std::vector<double> r;
    for (const ParticleSpec& p : particles) {
        const double rho = local_air(model.world.air, model.room, p.position.y).density_kg_m3;
        r.push_back(rho * (4.0 / 3.0) * std::numbers::pi * p.radius * p.radius * p.radius / p.mass);
    }
    return r;
}

// The scene's own run (`own`) against a run from starts moved by half the length tolerance
// (VariantAdvice::chaos), and the warning when that alone moves a metric beyond tolerance.
void measure_chaos(const Model& model, const std::vector<ParticleSpec>& particles, const RunOutcome& own,
                   const AdviceOptions& o, VariantAdvice& a) {
    const AdviceTolerances tol = o.tolerances();
    const double nudge = chaos_nudge * tol.metres;
    const RunOutcome again = observe_run(model, nudged(model, particles, nudge), o.max_duration_s, false, o.cancel);
    a.chaos.term = "nudged starts";
    a.chaos.in_scene = true;
    a.chaos.model = model.drag.model;  // the run's settings: the variant's own
    a.chaos.with_wind = model.world.wind.kind != WindKind::none;
    a.chaos.buoyancy = model.world.buoyancy;
    compare_runs(again, own, tol, a.chaos);
    a.chaos_measured = true;
    a.simulated_s = std::max(a.simulated_s, again.end_time);
    ++a.distinct_runs;
    if (a.chaos.matters)
        a.warnings.push_back(fmt::format("the trajectories are chaotic: moving every start by half the length tolerance ({}) "
                                         "changes {}; particle by particle, differences up to {:g}x these may be the "
                                         "scene's chaos rather than a term's own effect",
                                         quantity(nudge, "m", false), beyond_list(a.chaos), chaos_factor));
}

// The cheapest drag model whose run stays within tolerance of the reference on every metric
// (or beyond it only by the scene's chaos), and its verdict.
void choose_cheapest_drag(const Model& model, VariantAdvice& a) {
    bool by_chaos = false;
    for (const ModelRun& r : a.runs)
        if (r.alternative && !r.matters && r.not_applicable.empty()) {
            a.cheapest_adequate = r.model;
            by_chaos = r.within_chaos;
            break;
        }
    a.verdicts.push_back(fmt::format("cheapest drag model within tolerance of {}{}: '{}'; this variant uses '{}'",
                                     to_string(reference_drag), by_chaos ? " or of the scene's chaos" : "",
                                     to_string(a.cheapest_adequate), to_string(model.drag.model)));
}

// `particles`: the ones the runs follow (the first 100); `all`: the scene's, for the collision estimate.
VariantAdvice advise_variant(const Model& model, const std::vector<ParticleSpec>& particles,
                             std::span<const ParticleSpec> all, const AdviceOptions& o,
                             const std::function<void(double)>& progress) {
    VariantAdvice a;
    a.label = model.label;
    a.configured = model.drag.model;
    a.wind = model.world.wind.kind;
    a.buoyancy = model.world.buoyancy;
    a.density_ratio = density_ratios(model, particles);
    const AdviceTolerances tol = o.tolerances();

    RunPlan plan;
    plan.models.try_emplace(nullptr, model);  // the variant as configured
    const Builder reference = plan.key(model, use_reference_drag);
    // Rows that cannot be judged here (wind in a calm scene) need no runs.
    auto applicable = [&](const TermRow& row) {
        return !row.not_applicable || !row.not_applicable(model, particles.size());
    };
    std::vector<std::pair<Builder, Builder>> keys;
    for (const TermRow& row : term_table())
        keys.emplace_back(applicable(row) ? plan.key(model, row.measured) : nullptr,
                          applicable(row) ? plan.key(model, row.baseline) : nullptr);
    // The share done before each run: the distinct runs, and the nudged one when it is made.
    const bool chaos = model.collisions.enabled && particles.size() >= 2;
    const double total_runs = static_cast<double>(plan.models.size() + (chaos ? 1 : 0));
    std::map<Builder, RunOutcome> runs;
    runs[reference] = observe_run(plan.models.at(reference), particles, o.max_duration_s, true, o.cancel);
    for (const auto& [key, m] : plan.models)
        if (!runs.count(key)) {
            progress(static_cast<double>(runs.size()) / total_runs);
            runs[key] = observe_run(m, particles, o.max_duration_s, false, o.cancel);
        }
    for (const auto& [key, r] : runs) a.simulated_s = std::max(a.simulated_s, r.end_time);
    a.distinct_runs = runs.size();
    if (chaos) {
        progress(static_cast<double>(runs.size()) / total_runs);
        measure_chaos(model, particles, runs.at(nullptr), o, a);
    }

    const RunOutcome& ref = runs.at(reference);
    a.re_min = std::isfinite(ref.re_min) ? ref.re_min : 0.0;
    a.re_max = ref.re_max;
    a.max_drag_to_weight = ref.max_drag_to_weight;
    a.max_mach = ref.max_mach;
    a.stokes_error_factor = sphere_cd_times_re(a.re_max) / 24.0;

    // Over how long the particles move without collisions (the collisions row's baseline run).
    const double free_s = runs.at(keys[row_index(collisions_term)].second).end_time;
    a.collisions = estimate_collisions(model, all, free_s);
    a.collisions.measured_particles = particles.size();

    const std::span<const TermRow> table = term_table();
    for (std::size_t k = 0; k < table.size(); ++k) {
        const TermRow& row = table[k];
        ModelRun r;
        r.term = row.name;
        r.alternative = row.kind == TermKind::alternative;
        r.in_scene = row.in_scene(model);
        const Model& simpler = plan.models.at(row.kind == TermKind::toggle ? keys[k].second : keys[k].first);
        r.model = simpler.drag.model;
        r.with_wind = simpler.world.wind.kind != WindKind::none;
        r.buoyancy = simpler.world.buoyancy;
        if (const char* why = row.not_applicable ? row.not_applicable(model, particles.size()) : nullptr)
            r.not_applicable = why;
        else compare_runs(runs.at(keys[k].first), runs.at(keys[k].second), tol, r);
        // The collisions row is the chaos's source, not a small change within it: not marked.
        if (a.chaos.matters && std::string_view(row.name) != collisions_term) mark_chaos(a.chaos, tol, r);
        a.runs.push_back(r);
    }
    const std::size_t collisions_row = row_index(collisions_term);
    a.collisions_recommended = recommend_collisions(a.collisions, a.runs[collisions_row].matters);
    for (std::size_t k = 0; k < table.size(); ++k)
        if (table[k].verdict) a.verdicts.push_back(row_verdict(table[k], {model, a, a.runs[k], measured_words(a.runs[k], a.chaos, tol)}, tol));

    choose_cheapest_drag(model, a);
    add_warnings(model, a);
    return a;
}

}  // namespace

Advice advise(const Scene& scene, const AdviceOptions& o) {
    Advice advice;
    advice.tolerance_m = o.tolerance_m;
    advice.tolerances = o.tolerances();
    advice.max_duration_s = o.max_duration_s;
    const std::vector<ParticleSpec> all = initial_particles(scene);
    advice.particles_total = all.size();
    std::vector<ParticleSpec> particles(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(std::min(all.size(), max_advice_particles)));
    advice.particles_used = particles.size();
    const std::size_t variants = variant_count(scene);
    for (std::size_t v = 0; v < variants; ++v) {
        if (o.cancel && o.cancel->load(std::memory_order_relaxed)) {
            advice.cancelled = true;
            break;
        }
        // Progress: this variant's share of the variants, by its runs done.
        auto progress = [&](double within) {
            if (o.progress) o.progress((static_cast<double>(v) + within) / static_cast<double>(variants));
        };
        advice.variants.push_back(advise_variant(model_for_variant(scene, v), particles, all, o, progress));
        // Cancelled during its runs: the variant's advice is from runs cut short.
        if (o.cancel && o.cancel->load(std::memory_order_relaxed)) {
            advice.cancelled = true;
            break;
        }
    }
    if (o.progress && !advice.cancelled) o.progress(1.0);
    return advice;
}

}  // namespace pl
