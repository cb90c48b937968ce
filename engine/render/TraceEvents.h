#pragma once
// A run's frames as a trace in the Trace Event format (the JSON object form
// that Perfetto's UI and chrome://tracing open; "Trace Event Format", Google,
// docs.google.com/document/d/1CvAClvFfyA5R-PhYUmn5OOQtYMH4h6I0nSsKchNAySU):
//   {"traceEvents": [...], "displayTimeUnit": "ms", "otherData": {...}}
// One process; thread 1 "CPU" holds what the CPU spent recording each pass,
// thread 2 "GPU" what the GPU spent running it, between its two GL_TIMESTAMP
// stamps (gl/GpuProfiler.h). Each frame is a slice on both threads ("frame N",
// category "frame") around its passes' slices (category "pass"; warm-up
// frames' are "pass,warm_up"), and each pass the graph culled in a frame is an
// instant event on the CPU thread at the frame's start ("culled: NAME", args
// {"because": ...}). Times are microseconds ("ts", "dur") since the profiler
// was made; a slice's "dur" is the pass's gpu_ms or cpu_ms in the timings
// times 1000. A GPU slice that would begin before the previous one on its
// thread ended (stamps of a GPU whose clock is not monotonic across passes)
// begins where that one ended instead, so that slices on a thread nest; its
// "dur" stays the measured one and its args keep the stamped begin.

#include "render/FrameTimings.h"

#include <string>

namespace dermis {

std::string traceEventsJson(const FrameTimings& timings, const RunInfo& info);

}  // namespace dermis
