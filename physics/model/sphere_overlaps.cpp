#include "physics/model/sphere_overlaps.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace pl {
namespace {

// Cell numbers stay below 2^40 along an axis: the round-off of (x - origin) / cell is then below
// 2^-12 of a cell, and a cell 1/256 wider than the spheres of its level keeps two spheres that
// touch within one cell of each other along every axis.
constexpr double most_cells_per_axis = 0x1p40;
constexpr double cell_slack = 1.0 + 1.0 / 256.0;
// Work (cell lookups and sphere tests) allowed per sphere, on top of the overlaps counted: a
// sphere looks through 27 cells on at most 41 levels (the base cell is at least 2^-40 of the
// largest diameter).
constexpr std::size_t work_per_sphere = 27 * 48 + 64;

struct CellKey {
    std::int64_t x = 0, y = 0, z = 0;
    int level = -1;  // -1: an empty slot
    friend bool operator==(const CellKey&, const CellKey&) = default;
};

std::uint64_t hash_of(const CellKey& k) {
    // Multiplicative mixing of the four numbers (odd 64-bit constants); the high bits are folded
    // into the low ones, which the table's mask keeps.
    std::uint64_t h = static_cast<std::uint64_t>(k.x) * 0x9E3779B97F4A7C15ull;
    h ^= static_cast<std::uint64_t>(k.y) * 0xC2B2AE3D27D4EB4Full;
    h ^= static_cast<std::uint64_t>(k.z) * 0x165667B19E3779F9ull;
    h ^= static_cast<std::uint64_t>(k.level) * 0xD6E8FEB86659FD93ull;
    return h ^ (h >> 29);
}

// The spheres' cells, on every level: each cell's members, found from its key by open addressing.
class LevelGrid {
public:
    explicit LevelGrid(std::span<const Sphere> spheres);

    int level_of(std::size_t i) const { return level_[i]; }
    const std::vector<int>& levels() const { return levels_; }  // the levels that hold spheres, ascending
    CellKey cell_of(const Vec3& centre, int level) const {
        const double size = std::ldexp(base_, level);
        const Vec3 u = (centre - origin_) / size;  // >= 0, below 2^40
        return {static_cast<std::int64_t>(u.x), static_cast<std::int64_t>(u.y), static_cast<std::int64_t>(u.z), level};
    }
    // The members of the cell with this key (empty when none).
    std::span<const std::uint32_t> members(const CellKey& key) const {
        const std::uint32_t id = table_[slot_of(key)];
        if (id == empty) return {};
        return {members_.data() + start_[id], members_.data() + start_[id + 1]};
    }

private:
    static constexpr std::uint32_t empty = 0xffffffffu;
    // The slot that holds the key's cell, or the empty slot where it would go (linear probing).
    std::uint64_t slot_of(const CellKey& key) const {
        std::uint64_t slot = hash_of(key) & mask_;
        while (table_[slot] != empty && !(keys_[table_[slot]] == key)) slot = (slot + 1) & mask_;
        return slot;
    }
    std::uint32_t insert(const CellKey& key);

    Vec3 origin_{0.0};
    double base_ = 1.0;  // level 0's cell, m
    std::vector<int> level_, levels_;
    std::vector<std::uint32_t> table_;  // cell ids, by hash slot
    std::uint64_t mask_ = 0;
    std::vector<CellKey> keys_;          // by cell id
    std::vector<std::uint32_t> start_;   // by cell id: its first member in members_
    std::vector<std::uint32_t> members_;  // sphere indices, cell by cell
};

LevelGrid::LevelGrid(std::span<const Sphere> spheres) : level_(spheres.size()) {
    Vec3 low = spheres[0].centre, high = low;
    double smallest = 2.0 * spheres[0].radius, largest = smallest;
    for (const Sphere& s : spheres) {
        low = glm::min(low, s.centre);
        high = glm::max(high, s.centre);
        smallest = std::min(smallest, 2.0 * s.radius);
        largest = std::max(largest, 2.0 * s.radius);
    }
    const Vec3 span = high - low;
    origin_ = low;
    base_ = std::max({smallest, std::max({span.x, span.y, span.z}) / most_cells_per_axis, largest / most_cells_per_axis}) *
            cell_slack;
    for (std::size_t i = 0; i < spheres.size(); ++i) {
        const double need = 2.0 * spheres[i].radius * cell_slack;
        int level = std::max(0, std::ilogb(need / base_));
        while (level > 0 && std::ldexp(base_, level - 1) >= need) --level;
        while (std::ldexp(base_, level) < need) ++level;
        level_[i] = level;
    }
    levels_ = level_;
    std::sort(levels_.begin(), levels_.end());
    levels_.erase(std::unique(levels_.begin(), levels_.end()), levels_.end());

    std::size_t slots = 16;
    while (slots < 2 * spheres.size()) slots *= 2;
    table_.assign(slots, empty);
    mask_ = slots - 1;
    std::vector<std::uint32_t> cell(spheres.size());
    for (std::size_t i = 0; i < spheres.size(); ++i) cell[i] = insert(cell_of(spheres[i].centre, level_[i]));
    start_.assign(keys_.size() + 1, 0);
    for (const std::uint32_t c : cell) ++start_[c + 1];
    for (std::size_t c = 0; c < keys_.size(); ++c) start_[c + 1] += start_[c];
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    members_.resize(spheres.size());
    for (std::size_t i = 0; i < spheres.size(); ++i) members_[fill[cell[i]]++] = static_cast<std::uint32_t>(i);
}

std::uint32_t LevelGrid::insert(const CellKey& key) {
    std::uint32_t& id = table_[slot_of(key)];
    if (id == empty) {
        id = static_cast<std::uint32_t>(keys_.size());
        keys_.push_back(key);
    }
    return id;
}

// Counts one sphere's overlaps on one level (same_level: only with higher indices), till the
// limit or the budget.
class Counter {
public:
    Counter(std::span<const Sphere> spheres, const LevelGrid& grid, std::size_t limit, double tolerance)
        : spheres_(spheres), grid_(grid), limit_(limit), keep_(1.0 - tolerance),
          budget_(work_per_sphere * spheres.size() + 4 * limit) {}

    // False once the count is over the limit or the budget is spent.
    bool look(std::uint32_t i, int level) {
        const bool same_level = level == grid_.level_of(i);
        const CellKey home = grid_.cell_of(spheres_[i].centre, level);
        for (std::int64_t dz = -1; dz <= 1; ++dz)
            for (std::int64_t dy = -1; dy <= 1; ++dy)
                for (std::int64_t dx = -1; dx <= 1; ++dx) {
                    const std::span<const std::uint32_t> near =
                        grid_.members({home.x + dx, home.y + dy, home.z + dz, level});
                    work_ += 1 + near.size();
                    for (const std::uint32_t j : near)
                        if ((!same_level || j > i) && !test(i, j)) return false;
                    if (work_ > budget_) {
                        result_.undecided = true;
                        return false;
                    }
                }
        return true;
    }
    const OverlapCount& result() const { return result_; }

private:
    bool test(std::uint32_t i, std::uint32_t j) {
        const double contact = spheres_[i].radius + spheres_[j].radius;
        const double distance = glm::distance(spheres_[i].centre, spheres_[j].centre);
        if (!(distance < contact * keep_)) return true;
        const double share = (contact - distance) / contact;
        if (share > result_.deepest_share) {
            result_.deepest_share = share;
            result_.deepest_depth = contact - distance;
            result_.deepest_a = std::min(i, j);
            result_.deepest_b = std::max(i, j);
        }
        if (++result_.pairs <= limit_) return true;
        result_.over_limit = true;
        return false;
    }

    std::span<const Sphere> spheres_;
    const LevelGrid& grid_;
    std::size_t limit_;
    double keep_;
    std::size_t budget_, work_ = 0;
    OverlapCount result_;
};

}  // namespace

OverlapCount count_overlaps(std::span<const Sphere> spheres, std::size_t limit, double tolerance) {
    if (spheres.size() < 2) return {};
    const LevelGrid grid(spheres);
    Counter counter(spheres, grid, limit, tolerance);
    // Each sphere's own level first, for all of them: a clump of like balls is counted there,
    // with work bounded by the overlaps it finds, before any sphere looks through other levels.
    for (std::uint32_t i = 0; i < spheres.size(); ++i)
        if (!counter.look(i, grid.level_of(i))) return counter.result();
    for (std::uint32_t i = 0; i < spheres.size(); ++i)
        for (const int level : grid.levels())
            if (level > grid.level_of(i) && !counter.look(i, level)) return counter.result();
    return counter.result();
}

}  // namespace pl
