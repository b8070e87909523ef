// CSV rows with numbers in the shortest form that reads back to the same double
// (std::to_chars), so studies can compare written results to 1e-12 and beyond.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>

namespace pl {

// Shortest round-trip decimal form of `value` ("nan", "inf", "-inf" for non-finite values).
std::string format_double(double value);

// Writes one CSV row at a time to a stream the caller owns. Fields with commas, quotes or line
// breaks are quoted (RFC 4180).
class CsvWriter {
public:
    explicit CsvWriter(std::ostream& out) : out_(out) {}

    CsvWriter& field(double value);
    CsvWriter& field(std::uint64_t value);
    CsvWriter& field(std::int64_t value);
    CsvWriter& field(int value) { return field(static_cast<std::int64_t>(value)); }
    CsvWriter& field(std::string_view text);
    CsvWriter& field(const char* text) { return field(std::string_view(text)); }
    void end_row();

private:
    void separator();
    std::ostream& out_;
    bool first_ = true;
};

}  // namespace pl
