#pragma once
// What `dermis tune` measures: at each camera distance, the finest SSS choice
// and every candidate rendered, each candidate's loss against the finest, and
// the cheapest within margin x budget (bench/QualityTune.h) as a row of the
// quality table (scene/QualityTable.h).

#include "measure/Session.h"

#include "core/Result.h"
#include "scene/QualityTable.h"

#include <string>
#include <vector>

namespace dermis::measure {

struct TuneSettings {
    std::string scenePath;
    int width = 0;
    int height = 0;
    std::vector<double> distances;  // factors of the camera's distance to its target
    int frames = 3;                 // timed per render, after one warm-up
    double budget = 0.01;           // relative RMSE against the finest
    double margin = 0.8;            // a candidate qualifies within margin x budget
};

// The table, its rows sorted by pixels per mm. Fails where no SSS pixel is seen
// or two distances give the same scale. The session's camera and SSS settings
// are left at the last render's.
Result<QualityTable> tuneQualityTable(Session& session, const TuneSettings& settings);

}  // namespace dermis::measure
