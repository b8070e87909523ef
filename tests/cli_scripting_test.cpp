// The pieces behind `run`'s scripting options: --particles lists, the trajectory size warning,
// --set overrides on a preset document, the .npy header, and CSV flattened from JSON.
#include "cli/trajectory_options.hpp"
#include "io/json_csv.hpp"
#include "io/npy_writer.hpp"
#include "io/preset_overrides.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sstream>

namespace pl {
namespace {

TEST(ParticleList, RangesAndSingleIndicesSortedWithoutDuplicates) {
    std::vector<std::size_t> out;
    EXPECT_EQ(cli::parse_particle_list("5,0,3-5", 10, out), "");
    EXPECT_EQ(out, (std::vector<std::size_t>{0, 3, 4, 5}));
}

TEST(ParticleList, ErrorsNameTheBadItem) {
    std::vector<std::size_t> out;
    EXPECT_NE(cli::parse_particle_list("0,x", 10, out).find("'x'"), std::string::npos);
    EXPECT_NE(cli::parse_particle_list("5-3", 10, out).find("'5-3'"), std::string::npos);
    EXPECT_NE(cli::parse_particle_list("0,,1", 10, out).find("''"), std::string::npos);
    EXPECT_NE(cli::parse_particle_list("2-10", 10, out).find("particle 10 does not exist"), std::string::npos);
}

TEST(TrajectorySize, WarnsBeyondTheThresholdNamingTheRemedies) {
    // 10 000 particles every step for 5 s at dt = 2 ms: 2502 output points.
    const std::uint64_t rows = cli::trajectory_rows_bound(2500, 1, 10000, 1);
    EXPECT_EQ(rows, 2502u * 10000u);
    const std::string warning = cli::trajectory_size_warning("t.csv", rows * 250);
    EXPECT_NE(warning.find("6.3 GB"), std::string::npos) << warning;
    EXPECT_NE(warning.find("--every"), std::string::npos);
    EXPECT_NE(warning.find("--particles"), std::string::npos);
    EXPECT_EQ(cli::trajectory_size_warning("t.csv", cli::trajectory_rows_bound(2500, 100, 10000, 1) * 250), "");
}

nlohmann::json overridden(const std::string& doc, const std::vector<std::string>& sets) {
    const OverrideResult r = apply_preset_overrides(doc, sets);
    EXPECT_EQ(r.error, "");
    return nlohmann::json::parse(r.text);
}

TEST(PresetOverrides, SetNestedKeysArrayElementsAndBareWords) {
    const std::string doc = R"({"drag": {"model": "none"}, "particles": [{"mass": 1}, {"mass": 2}]})";
    const nlohmann::json j = overridden(doc, {"drag.model=quadratic", "drag.cd=0.6", "particles[1].velocity=[5,5,0]",
                                              "world.wind.kind=constant"});
    EXPECT_EQ(j["drag"]["model"], "quadratic");
    EXPECT_EQ(j["drag"]["cd"], 0.6);
    EXPECT_EQ(j["particles"][1]["velocity"], nlohmann::json::parse("[5,5,0]"));
    EXPECT_EQ(j["particles"][1]["mass"], 2);
    EXPECT_EQ(j["world"]["wind"]["kind"], "constant");  // created: the preset reader judges it
}

TEST(PresetOverrides, PathsThatNameNothingAreErrorsNamingThem) {
    const std::string doc = R"({"drag": {"model": "none"}, "particles": [{"mass": 1}]})";
    EXPECT_NE(apply_preset_overrides(doc, {"particles[1].mass=2"}).error.find("particles has 1 element"), std::string::npos);
    EXPECT_NE(apply_preset_overrides(doc, {"drag[0]=1"}).error.find("drag is not an array"), std::string::npos);
    EXPECT_NE(apply_preset_overrides(doc, {"drag.model.x=1"}).error.find("drag.model is not an object"), std::string::npos);
    for (const char* bad : {"drag.cd", "=1", "drag..cd=1", "drag.=1", "particles[x].mass=1", "particles[].mass=1"})
        EXPECT_NE(apply_preset_overrides(doc, {bad}).error.find("expected KEY=VALUE"), std::string::npos) << bad;
}

TEST(PresetOverrides, ADocumentThatIsNotJsonIsLeftToTheReader) {
    const OverrideResult r = apply_preset_overrides("{ not json", {"drag.cd=1"});
    EXPECT_EQ(r.error, "");
    EXPECT_EQ(r.text, "{ not json");
}

TEST(Npy, HeaderIsAlignedAndHoldsTheRowCount) {
    std::stringstream out;
    auto sink = make_npy_trajectory_sink(out);
    StateRow row;
    row.step = 7;
    row.y_m = 1.5;
    sink->write(row, "label");
    sink->write(row, "label");
    ASSERT_TRUE(sink->finish());
    const std::string bytes = out.str();
    ASSERT_EQ(bytes.substr(0, 6), "\x93NUMPY");
    const std::size_t header = 10 + static_cast<unsigned char>(bytes[8]) + 256u * static_cast<unsigned char>(bytes[9]);
    EXPECT_EQ(header % 64, 0u);
    EXPECT_NE(bytes.find("'shape': (2,)"), std::string::npos);
    EXPECT_EQ(bytes.size(), header + 2 * sink->row_bytes());
    EXPECT_EQ(sink->row_bytes(), 17u * 8u);  // every column but the label
    EXPECT_NE(npy_dtype_description().find("('step', '<u8'), ('t_s', '<f8'), ('variant_index', '<u8')"), std::string::npos);
}

TEST(JsonCsv, NestedObjectsBecomeColumnsAndAnArrayCanBeExploded) {
    const auto rows = nlohmann::ordered_json::parse(
        R"([{"label": "a", "m": {"x_m": 1.5, "t_s": null}, "notes": ["p", "q"], "runs": [{"k": 1}, {"k": 2}]}])");
    std::ostringstream flat, exploded;
    write_json_rows_csv(flat, rows);
    write_json_rows_csv(exploded, rows, "runs");
    EXPECT_EQ(exploded.str(), "label,m.x_m,m.t_s,notes,runs.k\na,1.5,,p; q,1\na,1.5,,p; q,2\n");
    EXPECT_EQ(flat.str().substr(0, flat.str().find('\n')), "label,m.x_m,m.t_s,notes,runs");
}

}  // namespace
}  // namespace pl
