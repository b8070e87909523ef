// An output named on the command line: a file, written whole or not at all (io/atomic_output:
// a temporary file renamed over the target on close), or standard output for "-".
#pragma once

#include "io/atomic_output.hpp"

#include <memory>
#include <ostream>
#include <string>

namespace pl::cli {

class OutputStream {
public:
    // Opens `path` for writing ("-": standard output); false when the file cannot be opened,
    // and error() says why.
    bool open(const std::string& path);
    const std::string& error() const;
    bool is_open() const { return open_; }
    bool is_stdout() const { return to_stdout_; }
    std::ostream& stream();
    // Flushes and closes (renames the complete file over the target); false when any write
    // failed, and error() says why. An output never closed leaves the target as it was.
    bool close();

private:
    std::unique_ptr<AtomicOutput> file_;
    std::string error_;
    bool open_ = false, to_stdout_ = false;
};

}  // namespace pl::cli
