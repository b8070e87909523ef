// Things that happen to particles: bounces, coming to rest, lifting off, numerical failure.
#pragma once

#include <cstdint>
#include <string>

namespace pl {

enum class EventKind : std::uint8_t {
    bounce,  // hit a wall and rebounded
    rest,    // rebound speed below rest_speed: normal velocity zeroed, now resting on the wall
    stop,    // a resting particle's sliding stopped: velocity exactly zero
    lift,    // left a wall it was resting on (a force pulled it off or it was kicked)
    frozen,  // state became non-finite: restored to the last finite state and frozen
};
const char* to_string(EventKind k);

struct Event {
    double t = 0.0;
    std::uint32_t particle = 0;
    std::int8_t wall = -1;  // Wall, or -1 when no wall is involved
    EventKind kind = EventKind::bounce;
    double speed_in = 0.0;   // |v| just before
    double speed_out = 0.0;  // |v| just after
};

}  // namespace pl
