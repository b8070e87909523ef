// An output named on the command line: a file, or standard output for "-".
#pragma once

#include <fstream>
#include <ostream>
#include <string>

namespace pl::cli {

class OutputStream {
public:
    // Opens `path` for writing ("-": standard output); false when the file cannot be opened.
    bool open(const std::string& path);
    bool is_open() const { return open_; }
    bool is_stdout() const { return to_stdout_; }
    std::ostream& stream();
    // Flushes and closes; false when any write failed.
    bool close();

private:
    std::ofstream file_;
    bool open_ = false, to_stdout_ = false;
};

}  // namespace pl::cli
