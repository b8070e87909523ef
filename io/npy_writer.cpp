#include "io/npy_writer.hpp"

#include <fmt/format.h>

#include <bit>
#include <cstring>

namespace pl {

namespace {

static_assert(std::endian::native == std::endian::little, "the .npy fields are written as little-endian");

// The header (after the 10-byte preamble) is padded so that the data starts at a multiple of 64
// bytes, as the format recommends; its shape field is padded to the widest count.
std::string npy_header(std::uint64_t rows) {
    std::string dict = fmt::format("{{'descr': {}, 'fortran_order': False, 'shape': ({},), }}", npy_dtype_description(), rows);
    const std::size_t widest = dict.size() - fmt::format("{}", rows).size() + 20;  // 20 digits: any uint64
    std::size_t total = 10 + widest + 1;
    total = (total + 63) / 64 * 64;
    dict.append(total - 10 - 1 - dict.size(), ' ');
    dict += '\n';
    const auto length = static_cast<std::uint16_t>(dict.size());
    std::string out = "\x93NUMPY";
    out += '\x01';
    out += '\x00';
    out += static_cast<char>(length & 0xff);
    out += static_cast<char>(length >> 8);
    return out + dict;
}

class NpyTrajectorySink final : public TrajectorySink {
public:
    explicit NpyTrajectorySink(std::ostream& out) : out_(out) { out_ << npy_header(0); }
    void write(const StateRow& row, std::string_view) override {
        for (const TrajectoryColumn& c : trajectory_columns()) {
            if (c.is_label()) continue;
            char bytes[8];
            if (c.integer) std::memcpy(bytes, &(row.*c.integer), 8);
            else std::memcpy(bytes, &(row.*c.real), 8);
            out_.write(bytes, 8);
        }
        ++rows_;
    }
    bool finish() override {
        out_.flush();
        out_.seekp(0);
        out_ << npy_header(rows_);
        out_.seekp(0, std::ios::end);
        return static_cast<bool>(out_);
    }
    std::uint64_t row_bytes() const override { return 8 * (trajectory_columns().size() - 1); }

private:
    std::ostream& out_;
    std::uint64_t rows_ = 0;
};

}  // namespace

std::string npy_dtype_description() {
    std::string d = "[";
    for (const TrajectoryColumn& c : trajectory_columns()) {
        if (c.is_label()) continue;
        d += fmt::format("{}('{}', '{}')", d.size() > 1 ? ", " : "", c.name, c.integer ? "<u8" : "<f8");
    }
    return d + "]";
}

std::unique_ptr<TrajectorySink> make_npy_trajectory_sink(std::ostream& out) {
    return std::make_unique<NpyTrajectorySink>(out);
}

}  // namespace pl
