#include "app/video_pipe.hpp"

#include "io/atomic_output.hpp"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <iterator>
#include <spawn.h>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace pl::app {

namespace fs = std::filesystem;

namespace {

// ffmpeg reads the frames bottom-up (GL's order), so every format starts with vflip. The GIF
// filter makes one palette per frame (stats_mode=single, new=1) so frames stream through
// instead of being held until a whole-video palette is known.
constexpr VideoFormat formats[] = {
    {".mp4", "MP4 (H.264)", "mp4", "-vf vflip -c:v libx264 -preset veryfast -crf 18 -pix_fmt yuv420p -movflags +faststart"},
    {".webm", "WebM (VP9)", "webm", "-vf vflip -c:v libvpx-vp9 -deadline realtime -cpu-used 8 -b:v 0 -crf 32 -pix_fmt yuv420p"},
    {".gif", "animated GIF", "gif", "-vf vflip,split[a][b];[a]palettegen=stats_mode=single[p];[b][p]paletteuse=new=1"},
};

std::string quoted(const fs::path& p) {
    std::string out = p.string();
    out.insert(out.begin(), '\'');  // not "'" + s: GCC 12 warns falsely (-Wrestrict) on that
    out += '\'';
    return out;
}

std::vector<std::string> ffmpeg_args(const VideoFormat& f, int width, int height, int fps, const fs::path& out) {
    std::vector<std::string> args = {"ffmpeg", "-hide_banner", "-loglevel", "error", "-y",
                                     "-f", "rawvideo", "-pix_fmt", "rgb24",
                                     "-s", std::to_string(width) + "x" + std::to_string(height),
                                     "-framerate", std::to_string(fps), "-i", "-"};
    std::istringstream codec(f.codec_args);
    args.insert(args.end(), std::istream_iterator<std::string>(codec), std::istream_iterator<std::string>());
    args.insert(args.end(), {"-f", f.muxer, out.string()});
    return args;
}

// The last line ffmpeg wrote to its log, for the error message.
std::string last_line(const fs::path& log) {
    std::ifstream in(log);
    std::string line, last;
    while (std::getline(in, line))
        if (!line.empty()) last = line;
    return last;
}

}  // namespace

const VideoFormat* video_formats(std::size_t& count) {
    count = std::size(formats);
    return formats;
}

const VideoFormat* video_format_for(const fs::path& file) {
    for (const VideoFormat& f : formats)
        if (file.extension() == f.extension) return &f;
    return nullptr;
}

std::string check_recording_target(const fs::path& file, const std::string& what) {
    if (video_format_for(file)) return {};
    std::string known;
    for (const VideoFormat& f : formats) known += std::string(known.empty() ? "" : ", ") + f.extension;
    return what + ": " + quoted(file) + " has no recording extension (" + known + ")";
}

VideoPipe::~VideoPipe() { cancel(); }

std::string VideoPipe::fail(const std::string& why) {
    cancel();
    return why;
}

std::string VideoPipe::open(const fs::path& target, int width, int height, int fps) {
    cancel();
    const VideoFormat* format = video_format_for(target);
    if (!format) return check_recording_target(target, "recording");
    target_ = write_target(target);
    const int tmp_fd = create_temp_beside(target_, tmp_);
    if (tmp_fd < 0) return "cannot write " + quoted(target) + ": " + std::strerror(errno);
    ::close(tmp_fd);
    const int log_fd = create_temp_beside(fs::temp_directory_path() / "particle-lab-ffmpeg.log", log_);
    if (log_fd < 0) return fail(std::string("cannot create ffmpeg's log file: ") + std::strerror(errno));
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) return fail(std::string("cannot create a pipe: ") + std::strerror(errno));
    // A write to an ffmpeg that died must fail with EPIPE, not kill the app.
    std::signal(SIGPIPE, SIG_IGN);

    const std::vector<std::string> args = ffmpeg_args(*format, width, height, fps, tmp_);
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[0], 0);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, log_fd, 2);
    const int rc = posix_spawnp(&pid_, "ffmpeg", &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[0]);
    ::close(log_fd);
    fd_ = fds[1];
    if (rc != 0) {
        pid_ = -1;
        if (rc == ENOENT)
            return fail("recording needs the ffmpeg program, which is not installed (Debian: apt install ffmpeg)");
        return fail(std::string("cannot start ffmpeg: ") + std::strerror(rc));
    }
    frame_bytes_ = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3;
    return {};
}

std::string VideoPipe::write_frame(const unsigned char* rgb) {
    if (!is_open()) return "no recording is open";
    std::size_t done = 0;
    while (done < frame_bytes_) {
        const ssize_t n = ::write(fd_, rgb + done, frame_bytes_ - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const std::string why = last_line(log_);
            return fail("ffmpeg stopped reading frames" + (why.empty() ? std::string{} : ": " + why));
        }
        done += static_cast<std::size_t>(n);
    }
    return {};
}

std::string VideoPipe::finish() {
    if (!is_open()) return "no recording is open";
    ::close(fd_);
    fd_ = -1;
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    pid_ = -1;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        const std::string why = last_line(log_);
        return fail("ffmpeg failed to write " + quoted(target_) + (why.empty() ? std::string{} : ": " + why));
    }
    // ffmpeg closed the file; sync it before the rename so a crash cannot leave an empty target.
    if (const int fd = ::open(tmp_.c_str(), O_RDONLY); fd >= 0) {
        ::fsync(fd);
        ::close(fd);
    }
    std::error_code ec;
    fs::rename(tmp_, target_, ec);
    if (ec) return fail("cannot write " + quoted(target_) + ": " + ec.message());
    tmp_.clear();
    cancel();  // removes the log
    return {};
}

void VideoPipe::cancel() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    if (pid_ > 0) {
        ::kill(pid_, SIGTERM);
        while (::waitpid(pid_, nullptr, 0) < 0 && errno == EINTR) {
        }
    }
    pid_ = -1;
    std::error_code ec;
    if (!tmp_.empty()) fs::remove(tmp_, ec);
    if (!log_.empty()) fs::remove(log_, ec);
    tmp_.clear();
    log_.clear();
}

}  // namespace pl::app
