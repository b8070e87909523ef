// The columns of `particle-lab run --out`, listed once: the CSV header and rows, the .npy dtype
// and the documentation all come from `trajectory_columns`. Names carry SI units (t_s, x_m,
// vx_m_s, kinetic_energy_J); `step` is the variant's own step count and t_s = step x dt, so a
// filter such as `t_s == 0.018` matches what the program computed.
#pragma once

#include "io/csv_writer.hpp"
#include "physics/stepping/simulation.hpp"

#include <cstdint>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace pl {

// One particle of one variant at one output point.
struct StateRow {
    std::uint64_t step = 0;
    double t_s = 0;
    std::uint64_t variant_index = 0;
    std::uint64_t particle = 0;
    double mass_kg = 0, radius_m = 0;
    double x_m = 0, y_m = 0, z_m = 0;
    double vx_m_s = 0, vy_m_s = 0, vz_m_s = 0;
    double speed_m_s = 0;
    double height_m = 0;  // above the floor (the room's lowest wall)
    double kinetic_energy_J = 0;
    double potential_energy_J = 0;  // m g h relative to the room's lowest point along g
    double total_energy_J = 0;      // kinetic + potential
};

// A column is an integer or a real member of StateRow, or (neither) the variant's label, which
// is text and appears in the CSV only (the binary format carries variant_index).
struct TrajectoryColumn {
    const char* name;
    std::uint64_t StateRow::*integer = nullptr;
    double StateRow::*real = nullptr;
    bool is_label() const { return integer == nullptr && real == nullptr; }
};

const std::vector<TrajectoryColumn>& trajectory_columns();

// "step,t_s,variant,...": the CSV header line's fields joined by `separator`.
std::string trajectory_column_names(const char* separator = ",");

StateRow state_row(const Simulation& sim, std::uint64_t variant_index, std::size_t particle);

// Where trajectory rows go: CSV (every column) or .npy (io/npy_writer.hpp: every column but the
// variant label).
class TrajectorySink {
public:
    virtual ~TrajectorySink() = default;
    virtual void write(const StateRow& row, std::string_view variant_label) = 0;
    // Completes the output (the .npy header's row count); false when that failed.
    virtual bool finish() { return true; }
    // Bytes one row takes, for the size estimate before a run.
    virtual std::uint64_t row_bytes() const = 0;
};

// Writes the header row now, then one row in the order of trajectory_columns() per write().
std::unique_ptr<TrajectorySink> make_csv_trajectory_sink(std::ostream& out);

}  // namespace pl
