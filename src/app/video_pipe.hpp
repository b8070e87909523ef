// Encodes raw RGB frames into a video or GIF by piping them to Debian's `ffmpeg` program (no
// encoder of our own). The output is written to a uniquely named temporary file beside the
// target (io/atomic_output) and renamed over it only when ffmpeg finished without error, so a
// failed or cancelled recording never leaves half a file nor destroys an older one.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <sys/types.h>

namespace pl::app {

// A container the recorder writes, chosen by the file's extension.
struct VideoFormat {
    const char* extension;    // ".mp4"
    const char* name;         // shown in the GUI: "MP4 (H.264)"
    const char* muxer;        // ffmpeg's -f
    const char* codec_args;   // encoder options after the input, before -f
};

// The formats, in the order the GUI offers them (one table: the GUI, the CLI check and the
// ffmpeg arguments all read it).
const VideoFormat* video_formats(std::size_t& count);

// The format for `file`'s extension, or null.
const VideoFormat* video_format_for(const std::filesystem::path& file);

// "" when `file` can be a recording, otherwise why not (naming `what`, e.g. "--record").
std::string check_recording_target(const std::filesystem::path& file, const std::string& what);

class VideoPipe {
public:
    VideoPipe() = default;
    ~VideoPipe();  // an unfinished pipe is cancelled: ffmpeg is stopped, the temporary file removed
    VideoPipe(const VideoPipe&) = delete;
    VideoPipe& operator=(const VideoPipe&) = delete;

    // Starts ffmpeg for frames of width x height (both even) at `fps`. Returns "" or why not
    // (ffmpeg missing, the folder not writable, ...).
    std::string open(const std::filesystem::path& target, int width, int height, int fps);
    bool is_open() const { return pid_ > 0; }
    // One frame of width*height*3 bytes, rows bottom-up as glReadPixels gives them (ffmpeg flips).
    // Returns "" or why it failed (the pipe is then cancelled).
    std::string write_frame(const unsigned char* rgb);
    // Closes the pipe, waits for ffmpeg and renames the file into place. Returns "" or why not.
    std::string finish();
    void cancel();

private:
    std::string fail(const std::string& why);  // cancels and returns `why`

    pid_t pid_ = -1;
    int fd_ = -1;  // ffmpeg's standard input
    std::size_t frame_bytes_ = 0;
    std::filesystem::path target_, tmp_, log_;
};

}  // namespace pl::app
