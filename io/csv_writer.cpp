#include "io/csv_writer.hpp"

#include <charconv>
#include <cmath>

namespace pl {

std::string format_double(double value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, value);
    return std::string(buf, r.ptr);
}

void CsvWriter::separator() {
    if (!first_) out_ << ',';
    first_ = false;
}

CsvWriter& CsvWriter::field(double value) {
    separator();
    out_ << format_double(value);
    return *this;
}

CsvWriter& CsvWriter::field(std::uint64_t value) {
    separator();
    out_ << value;
    return *this;
}

CsvWriter& CsvWriter::field(std::int64_t value) {
    separator();
    out_ << value;
    return *this;
}

CsvWriter& CsvWriter::field(std::string_view text) {
    separator();
    if (text.find_first_of(",\"\r\n") == std::string_view::npos) {
        out_ << text;
        return *this;
    }
    out_ << '"';
    for (char c : text) {
        if (c == '"') out_ << '"';
        out_ << c;
    }
    out_ << '"';
    return *this;
}

void CsvWriter::end_row() {
    out_ << '\n';
    first_ = true;
}

}  // namespace pl
