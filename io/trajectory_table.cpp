#include "io/trajectory_table.hpp"

#include "physics/stepping/energy.hpp"

namespace pl {

const std::vector<TrajectoryColumn>& trajectory_columns() {
    using R = StateRow;
    static const std::vector<TrajectoryColumn> columns = {
        {"step", &R::step},
        {"t_s", nullptr, &R::t_s},
        {"variant"},
        {"variant_index", &R::variant_index},
        {"particle", &R::particle},
        {"mass_kg", nullptr, &R::mass_kg},
        {"radius_m", nullptr, &R::radius_m},
        {"x_m", nullptr, &R::x_m},
        {"y_m", nullptr, &R::y_m},
        {"z_m", nullptr, &R::z_m},
        {"vx_m_s", nullptr, &R::vx_m_s},
        {"vy_m_s", nullptr, &R::vy_m_s},
        {"vz_m_s", nullptr, &R::vz_m_s},
        {"speed_m_s", nullptr, &R::speed_m_s},
        {"height_m", nullptr, &R::height_m},
        {"kinetic_energy_J", nullptr, &R::kinetic_energy_J},
        {"potential_energy_J", nullptr, &R::potential_energy_J},
        {"total_energy_J", nullptr, &R::total_energy_J},
    };
    return columns;
}

std::string trajectory_column_names(const char* separator) {
    std::string names;
    for (const TrajectoryColumn& c : trajectory_columns()) names += (names.empty() ? "" : separator) + std::string(c.name);
    return names;
}

namespace {

class CsvTrajectorySink final : public TrajectorySink {
public:
    explicit CsvTrajectorySink(std::ostream& out) : csv_(out) {
        for (const TrajectoryColumn& c : trajectory_columns()) csv_.field(c.name);
        csv_.end_row();
    }
    void write(const StateRow& row, std::string_view variant_label) override {
        for (const TrajectoryColumn& c : trajectory_columns()) {
            if (c.integer) csv_.field(row.*c.integer);
            else if (c.real) csv_.field(row.*c.real);
            else csv_.field(variant_label);
        }
        csv_.end_row();
    }
    // Measured on typical runs: about 18 numbers of 4-20 characters each.
    std::uint64_t row_bytes() const override { return 250; }

private:
    CsvWriter csv_;
};

}  // namespace

std::unique_ptr<TrajectorySink> make_csv_trajectory_sink(std::ostream& out) {
    return std::make_unique<CsvTrajectorySink>(out);
}

StateRow state_row(const Simulation& sim, std::uint64_t variant_index, std::size_t i) {
    const ParticleState& s = sim.state();
    const Model& m = sim.model();
    const Vec3 v = s.velocity(i);
    StateRow r;
    r.step = sim.step_count();
    r.t_s = sim.time();  // step x dt
    r.variant_index = variant_index;
    r.particle = i;
    r.mass_kg = s.mass[i];
    r.radius_m = s.radius[i];
    r.x_m = s.x[i];
    r.y_m = s.y[i];
    r.z_m = s.z[i];
    r.vx_m_s = v.x;
    r.vy_m_s = v.y;
    r.vz_m_s = v.z;
    r.speed_m_s = glm::length(v);
    r.height_m = s.y[i] - m.room.floor_y();
    r.kinetic_energy_J = kinetic_energy(s.mass[i], v);
    r.potential_energy_J = potential_energy(m.world.gravity, m.room, s.mass[i], s.position(i));
    r.total_energy_J = r.kinetic_energy_J + r.potential_energy_J;
    return r;
}

}  // namespace pl
