// Files written whole or not at all: the text goes to a temporary file with a unique name in
// the target's folder (mkstemp), and only a complete, flushed file is renamed over the target.
// A full disk, a crash or a signal therefore never leaves half a file nor loses the old one,
// and two writers of the same target never share a temporary file. A target that exists and is
// not a regular file (a device such as /dev/stdout, a FIFO) is written directly.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

namespace pl {

// The file a write to `path` should replace: `path` itself, or where its symlinks lead (so a
// linked file is updated through the link instead of the link becoming a regular file).
std::filesystem::path write_target(const std::filesystem::path& path);

// Creates `target`'s unique temporary sibling (mode 0666 minus the umask) and returns its
// descriptor, or -1 with errno set. `tmp` receives its name.
int create_temp_beside(const std::filesystem::path& target, std::filesystem::path& tmp);

// Whether two paths name the same file (existing or not: compared by their resolved names).
bool same_file(const std::filesystem::path& a, const std::filesystem::path& b);

class AtomicOutput {
public:
    // Opens the temporary file; on failure ok() is false and error() says why (strerror).
    explicit AtomicOutput(const std::filesystem::path& target);
    ~AtomicOutput();  // removes the temporary file unless committed
    AtomicOutput(const AtomicOutput&) = delete;
    AtomicOutput& operator=(const AtomicOutput&) = delete;

    bool ok() const { return error_.empty(); }
    const std::string& error() const { return error_; }
    std::ostream& stream() { return out_; }
    // Flushes, syncs and renames over the target. False with error() set on failure; the target
    // is then unchanged and the temporary file removed.
    bool commit();
    // Removes the temporary file now (the target keeps its old contents).
    void discard();

private:
    std::filesystem::path target_, tmp_;
    std::ofstream out_;
    std::string error_;
};

}  // namespace pl
