#pragma once
// Measurements to and from JSON, for the session file:
//   {"show_in_exports": false, "items": [{"kind": "distance", "normal_axis": 2,
//     "points": [[i, j, k], [i, j, k]]}, ...]}
// Points are voxel positions of the volume the session opens.
#include <nlohmann/json.hpp>

#include "measurement_model.h"

namespace voxray {

nlohmann::json measurementsToJson(const MeasurementModel& m);
// Replaces the model's measurements. Throws Error (Input) naming the first bad entry (an
// unknown kind, a wrong point count, a non-finite coordinate); the model is then unchanged.
void measurementsFromJson(const nlohmann::json& j, MeasurementModel& m);

}  // namespace voxray
