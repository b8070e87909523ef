#include "cli/output_stream.hpp"

#include <cerrno>
#include <cstring>
#include <iostream>

namespace pl::cli {

bool OutputStream::open(const std::string& path) {
    to_stdout_ = path == "-";
    if (!to_stdout_) {
        file_ = std::make_unique<AtomicOutput>(path);
        error_ = file_->error();
    }
    open_ = to_stdout_ || file_->ok();
    return open_;
}

const std::string& OutputStream::error() const { return file_ && !file_->ok() ? file_->error() : error_; }

std::ostream& OutputStream::stream() { return to_stdout_ ? std::cout : file_->stream(); }

bool OutputStream::close() {
    if (!open_) return true;
    open_ = false;
    if (to_stdout_) {
        if (std::cout.flush()) return true;
        error_ = std::string("writing standard output failed: ") + std::strerror(errno ? errno : EIO);
        return false;
    }
    return file_->commit();
}

}  // namespace pl::cli
