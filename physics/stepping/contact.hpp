// Room walls: distances, inward normals and the collision response (restitution + Coulomb
// friction as an impulse). Pure functions, shared by the stepping kernels.
#pragma once

#include "physics/stepping/particle_state.hpp"
#include "physics/model/scene.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pl {

struct RoomBounds {
    Vec3 lo, hi;  // the room's corners
    // Round-off of a position in the room (m): 4 ulp of its largest coordinate.
    double round_off;
    explicit RoomBounds(const Room& r)
        : lo(r.min_corner()), hi(r.max_corner()),
          round_off(4.0 * std::numeric_limits<double>::epsilon() *
                    std::max({std::abs(lo.x), std::abs(lo.y), std::abs(lo.z), std::abs(hi.x), std::abs(hi.y), std::abs(hi.z)})) {}

    static int axis(int wall) { return wall >> 1; }
    static bool is_max(int wall) { return wall & 1; }
    static Vec3 inward_normal(int wall) {
        Vec3 n(0.0);
        n[axis(wall)] = is_max(wall) ? -1.0 : 1.0;
        return n;
    }
    // Coordinate of the sphere centre when it touches the wall.
    double contact_plane(int wall, double radius) const {
        return is_max(wall) ? hi[axis(wall)] - radius : lo[axis(wall)] + radius;
    }
    // Signed distance of a sphere of `radius` at `x` from the wall; < 0 means penetration.
    double distance(int wall, const Vec3& x, double radius) const {
        const int a = axis(wall);
        return is_max(wall) ? (hi[a] - radius) - x[a] : x[a] - (lo[a] + radius);
    }
    // Puts the centre inside the box the centre may occupy (guards round-off only).
    Vec3 clamp_inside(const Vec3& x, double radius) const {
        Vec3 c = x;
        for (int a = 0; a < 3; ++a) {
            const double l = lo[a] + radius, h = hi[a] - radius;
            c[a] = l <= h ? glm::clamp(c[a], l, h) : 0.5 * (lo[a] + hi[a]);
        }
        return c;
    }
};

struct ImpactResult {
    Vec3 v_out{0.0};
    double normal_speed_in = 0.0;   // >= 0, toward the wall
    double normal_speed_out = 0.0;  // >= 0, away from the wall
    double bounce_loss_per_kg = 0.0;
    double friction_loss_per_kg = 0.0;
};

// Newton's restitution law on the normal velocity; the tangential velocity is reduced by the
// Coulomb friction impulse mu (1 + e) |v_n|, but never reversed (Stronge, Impact Mechanics, 2000).
inline ImpactResult impact(const Vec3& v, const Vec3& n, const ContactSettings& c) {
    ImpactResult r;
    const double vn = glm::dot(v, n);
    r.normal_speed_in = vn < 0.0 ? -vn : 0.0;
    r.normal_speed_out = c.restitution * r.normal_speed_in;
    const Vec3 vt = v - vn * n;
    const double vt_len = glm::length(vt);
    const double dvt = c.friction * (1.0 + c.restitution) * r.normal_speed_in;
    // Component by component, as selects (the contact kernel runs this eight particles at a time).
    const bool stops = vt_len <= dvt;
    const double keep = 1.0 - dvt / vt_len;
    const Vec3 vt_out(stops ? 0.0 : vt.x * keep, stops ? 0.0 : vt.y * keep, stops ? 0.0 : vt.z * keep);
    r.v_out = vt_out + r.normal_speed_out * n;
    r.bounce_loss_per_kg = 0.5 * (r.normal_speed_in * r.normal_speed_in - r.normal_speed_out * r.normal_speed_out);
    r.friction_loss_per_kg = 0.5 * (vt_len * vt_len - glm::dot(vt_out, vt_out));
    return r;
}

// Impacts on several walls at the same instant (a corner; `walls` is a bit mask of them):
// Newton's law on each wall's normal velocity, and one Coulomb friction impulse on the velocity
// tangent to all of them, mu times the sum of their normal impulses (1 + e) |v_n|, never
// reversing it. Applied one wall after the other, the first wall's friction also slowed the
// velocity into the second one, so a mirrored-symmetric hit came out asymmetric; here nothing
// depends on the order of the walls. normal_speed_in/out are sums over the walls.
inline ImpactResult corner_impact(const Vec3& v, std::uint8_t walls, const ContactSettings& c) {
    ImpactResult r;
    Vec3 normal_part(0.0), vt = v;
    for (int w = 0; w < 6; ++w) {
        if (!(walls & (1u << w))) continue;
        const Vec3 n = RoomBounds::inward_normal(w);
        const double vn = glm::dot(v, n);
        const double in = vn < 0.0 ? -vn : 0.0;
        r.normal_speed_in += in;
        r.normal_speed_out += c.restitution * in;
        r.bounce_loss_per_kg += 0.5 * (1.0 - c.restitution * c.restitution) * in * in;
        vt -= vn * n;
        normal_part += (vn < 0.0 ? c.restitution * in : vn) * n;
    }
    const double vt_len = glm::length(vt);
    const double dvt = c.friction * (1.0 + c.restitution) * r.normal_speed_in;
    const Vec3 vt_out = vt_len <= dvt ? Vec3(0.0) : vt * (1.0 - dvt / vt_len);
    r.v_out = vt_out + normal_part;
    r.friction_loss_per_kg = 0.5 * (vt_len * vt_len - glm::dot(vt_out, vt_out));
    return r;
}

}  // namespace pl
