#include "physics/stepping/kernel.hpp"

namespace pl {

void EventSink::end_step() const {
    if (events->size() > max_pending) {
        // Nobody is draining: keep the newest events, count the rest, stay bounded in memory.
        const std::size_t drop = events->size() - max_pending / 2;
        events->erase(events->begin(), events->begin() + static_cast<std::ptrdiff_t>(drop));
        *dropped += drop;
    }
}

void WarningSink::raise(WarningKind kind, std::uint32_t particle, double t, double value, bool above_range) const {
    const auto bit = static_cast<WarningBits>(1u << (above_range ? drag_above_range_bit : static_cast<unsigned>(kind)));
    if ((*warned)[particle] & bit) return;
    (*warned)[particle] |= bit;
    warnings->push_back({kind, particle, t, value});
}

}  // namespace pl
