#include "io/atomic_output.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace pl {

namespace fs = std::filesystem;

namespace {

std::string quoted(const fs::path& p) {
    std::string out(1, '\'');
    out += p.string();
    out += '\'';
    return out;
}

mode_t default_file_mode() {
    const mode_t mask = ::umask(0);  // the only way to read the umask is to set it
    ::umask(mask);
    return 0666 & ~mask;
}

}  // namespace

fs::path write_target(const fs::path& path) {
    fs::path p = path;
    std::error_code ec;
    // Bounded, so a symlink loop ends (the kernel's own limit is 40).
    for (int hops = 0; hops < 40 && fs::is_symlink(fs::symlink_status(p, ec)); ++hops) {
        const fs::path link = fs::read_symlink(p, ec);
        if (ec) break;
        p = link.is_absolute() ? link : p.parent_path() / link;
    }
    return p;
}

int create_temp_beside(const fs::path& target, fs::path& tmp) {
    std::string name = target.string() + ".tmp.XXXXXX";
    const int fd = ::mkstemp(name.data());
    if (fd < 0) return -1;
    ::fchmod(fd, default_file_mode());
    tmp = name;
    return fd;
}

bool same_file(const fs::path& a, const fs::path& b) {
    std::error_code ec_a, ec_b;
    if (fs::equivalent(a, b, ec_a)) return true;
    const fs::path ca = fs::weakly_canonical(a, ec_a), cb = fs::weakly_canonical(b, ec_b);
    return !ec_a && !ec_b && ca == cb;
}

AtomicOutput::AtomicOutput(const fs::path& target) : target_(write_target(target)) {
    std::error_code ec;
    const fs::file_status status = fs::status(target_, ec);
    if (fs::exists(status) && !fs::is_regular_file(status)) {
        // A device or a pipe (/dev/stdout, a FIFO): written directly, there is nothing to replace.
        out_.open(target_, std::ios::binary);
        if (!out_) error_ = "cannot open " + quoted(target) + " for writing: " + std::strerror(errno);
        return;
    }
    const int fd = create_temp_beside(target_, tmp_);
    if (fd < 0) {
        error_ = "cannot open " + quoted(target) + " for writing: cannot create a temporary file beside it: " +
                 std::strerror(errno);
        return;
    }
    ::close(fd);
    out_.open(tmp_, std::ios::binary | std::ios::trunc);
    if (!out_) error_ = "cannot open " + quoted(tmp_) + " for writing: " + std::strerror(errno);
}

AtomicOutput::~AtomicOutput() { discard(); }

void AtomicOutput::discard() {
    if (tmp_.empty()) return;
    if (out_.is_open()) out_.close();
    ::unlink(tmp_.c_str());
    tmp_.clear();
}

bool AtomicOutput::commit() {
    if (!ok()) return false;
    out_.flush();
    const bool written = static_cast<bool>(out_);
    const int write_errno = errno;
    out_.close();
    if (!written || !out_) {
        error_ = "writing " + quoted(target_) + " failed: " + std::strerror(write_errno ? write_errno : EIO) +
                 (tmp_.empty() ? "" : " (the existing file is unchanged)");
        discard();
        return false;
    }
    if (tmp_.empty()) return true;  // written directly
    // fsync before rename: after a crash the target is the old file or the whole new one.
    if (const int fd = ::open(tmp_.c_str(), O_RDONLY | O_CLOEXEC); fd >= 0) {
        const int synced = ::fsync(fd);
        const int sync_errno = errno;
        ::close(fd);
        if (synced != 0) {
            error_ = "writing " + quoted(target_) + " failed: " + std::strerror(sync_errno) + " (the existing file is unchanged)";
            discard();
            return false;
        }
    }
    if (::rename(tmp_.c_str(), target_.c_str()) != 0) {
        error_ = "cannot rename " + quoted(tmp_) + " over " + quoted(target_) + ": " + std::strerror(errno);
        discard();
        return false;
    }
    tmp_.clear();
    return true;
}

}  // namespace pl
