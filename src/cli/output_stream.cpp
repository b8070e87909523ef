#include "cli/output_stream.hpp"

#include <iostream>

namespace pl::cli {

bool OutputStream::open(const std::string& path) {
    to_stdout_ = path == "-";
    if (!to_stdout_) file_.open(path, std::ios::binary);
    open_ = to_stdout_ || file_.is_open();
    return open_;
}

std::ostream& OutputStream::stream() { return to_stdout_ ? std::cout : file_; }

bool OutputStream::close() {
    if (!open_) return true;
    open_ = false;
    if (to_stdout_) return static_cast<bool>(std::cout.flush());
    file_.close();
    return static_cast<bool>(file_);
}

}  // namespace pl::cli
