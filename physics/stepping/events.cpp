#include "physics/stepping/events.hpp"

namespace pl {

const char* to_string(EventKind k) {
    switch (k) {
        case EventKind::bounce: return "bounce";
        case EventKind::rest: return "rest";
        case EventKind::stop: return "stop";
        case EventKind::lift: return "lift";
        case EventKind::frozen: return "frozen";
    }
    return "?";
}

}  // namespace pl
