// The words summary.json ("stop_reason") and the console give each reason a run stopped for;
// readers of a summary accept these and no others.
#pragma once

#include <utility>

#include "engine/stop_reason.hpp"

namespace granule {

inline constexpr std::pair<StopReason, const char*> kStopReasonNames[] = {
    {StopReason::kTimeReached, "time reached"},
    {StopReason::kCollisionsReached, "collisions reached"},
    {StopReason::kNoEvents, "no further events"},
    {StopReason::kInelasticCollapse, "inelastic collapse"},
    {StopReason::kInterrupted, "interrupted"},
};

}  // namespace granule
