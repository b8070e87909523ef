// Performs the requests the panels and keys raised (reset, single step, run to the next event,
// launch again) at a safe point of the frame, before physics stepping.
#pragma once

#include "app/physics_driver.hpp"
#include "ui/lab_session.hpp"

namespace pl::app {

struct RequestOutcome {
    bool state_jumped = false;  // positions changed discontinuously (trails must restart)
};

// `after_step` runs after every base step taken here (trails, live metrics; what it returns is not needed).
RequestOutcome perform_state_requests(ui::LabSession& session, const AfterSteps& after_step);

}  // namespace pl::app
