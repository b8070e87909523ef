// The particles a struck particle's new path reaches outside the swept box it was paired by
// (CollisionPass, collision_pass.hpp).
//
// The broad phase pairs particles by the boxes of their straight paths over the step. An impact
// bends a path: a ball at rest in a row of balls 0.1 mm apart, struck at 8 m/s with dt = 1 ms,
// moves 8 mm on through the next ball, whose box its own box (at rest) did not meet. Unpaired,
// the two passed into each other unseen (14% of the contact distance at 1 ms, 70% at 5 ms, no
// warning), and the row took one ball a step instead of passing the blow on inside the step.
// So after each impact the box of the struck particle's path from the impact to the step's end
// is compared with the boxes it already covered; where it leaves them, the particles the pair
// cache's grid holds near the new box are taken, each whose swept box (or, if its own path left
// that, the box it covered) meets the new box is paired with it, and the pair's first contact is
// searched like any other. Not found: two particles whose bent paths meet where neither one's
// box in the grid reaches (both struck away from where they were paired, into one place); they
// meet at the next step, as every such pair did before. (Looking through every bent path each
// time made the pour of 10,000 balls, 7,700 impacts a step, ten times slower.) The pass stays
// event-driven and in time order; on one thread, in a fixed order: the same bits on any number
// of threads.
#include "physics/collide/collision_pass.hpp"

#include <algorithm>

namespace pl::collide {

bool CollisionPass::paired(std::uint32_t i, std::uint32_t j) const {
    const Pair p{std::min(i, j), std::max(i, j)};
    if (has_row(i))
        for (std::uint32_t k = pair_start_[row_[i]]; k < pair_start_[row_[i] + 1]; ++k)
            if (pairs_[pair_of_[k]] == p) return true;
    bool found = false;
    for_added_pairs_of(i, [&](std::uint32_t k) { found = found || pairs_[k] == p; });
    return found;
}

void CollisionPass::add_pair(const ParticleState& s, std::uint32_t i, std::uint32_t j, double h) {
    const auto k = static_cast<std::uint32_t>(pairs_.size());
    pairs_.push_back({std::min(i, j), std::max(i, j)});
    pair_queued_.push_back(0);
    for (const std::uint32_t x : {i, j}) {
        if (added_head_[x] == no_link) added_particles_.push_back(x);
        added_links_.push_back({k, added_head_[x]});
        added_head_[x] = static_cast<std::uint32_t>(added_links_.size() - 1);
    }
    ++added_total_;
    // A particle in no pair until now has no path yet: its straight one, and it joins the
    // paired particles (whose end positions are kept inside the room).
    if (!has_row(j) && !listed_[j]) {
        listed_[j] = 1;
        path_start_[j] = start_[j];
        path_time_[j] = 0.0;
        path_rate_[j] = (s.position(j) - start_[j]) / h;
        pair_particles_.push_back(j);
    }
}

void CollisionPass::reach_new_path(const ParticleState& s, std::uint32_t i, double h) {
    const double r = s.radius[i];
    SweptBox path = box_around(path_start_[i], at(i, h), r);
    if (contains(cover_of_[i] ? covers_[cover_of_[i] - 1] : boxes_.box[i], path)) return;
    // Looked up with a skin: a ball of a pile struck again and again in a step bends its path
    // each time, a little, and each bend left the box covered so far by a hair (the pour of
    // 10,000 balls looked up 3.2 times per struck ball and step). With a fiftieth of a radius
    // around it, once (1.06 times); the few pairs that adds whose balls never meet cost a root
    // each.
    const double skin = reach_skin * r;
    for (int k = 0; k < 3; ++k) {
        path.lo[k] -= skin;
        path.hi[k] += skin;
    }
    // The box its paths covered grows by this one: a particle that meets it later is paired.
    if (!cover_of_[i]) {
        covers_.push_back(boxes_.box[i]);
        reached_.push_back(i);
        cover_of_[i] = static_cast<std::uint32_t>(covers_.size());
    }
    SweptBox& cover = covers_[cover_of_[i] - 1];
    for (int k = 0; k < 3; ++k) {
        cover.lo[k] = std::min(cover.lo[k], path.lo[k]);
        cover.hi[k] = std::max(cover.hi[k], path.hi[k]);
    }
    near_.clear();
    if (pair_cache_.near(path, near_)) {
        std::sort(near_.begin(), near_.end());  // each once, in a fixed order
        near_.erase(std::unique(near_.begin(), near_.end()), near_.end());
    } else {
        near_.assign(boxes_.ids.begin(), boxes_.ids.end());  // sorted
    }
    for (const std::uint32_t j : near_) {
        if (j == i || s.frozen[j]) continue;
        const bool meets = overlap(path, boxes_.box[j]) || (cover_of_[j] && overlap(path, covers_[cover_of_[j] - 1]));
        if (meets && !paired(i, j)) add_pair(s, i, j, h);
    }
}

void CollisionPass::end_reach() {
    // The pairs in (a, b) order again for the contact solver; the step's lists cleared.
    if (!added_links_.empty()) {  // the added ones sorted, then merged into the broad phase's
        const auto added = pairs_.begin() + static_cast<std::ptrdiff_t>(broad_pairs_);
        std::sort(added, pairs_.end());
        std::inplace_merge(pairs_.begin(), added, pairs_.end());
    }
    for (const std::uint32_t x : added_particles_) added_head_[x] = no_link;
    for (const std::uint32_t x : reached_) cover_of_[x] = 0;
    for (std::size_t k = rows_; k < pair_particles_.size(); ++k) listed_[pair_particles_[k]] = 0;  // the added ones
    added_particles_.clear();
    added_links_.clear();
    reached_.clear();
    covers_.clear();
}

}  // namespace pl::collide
