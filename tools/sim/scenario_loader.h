#pragma once
#include <string>

#include "tools/sim/scenario.h"

namespace deepnav::sim {

// Reads a scenario file. Missing keys keep their defaults; an unknown key, a value of the wrong type or
// out of its range, or an inconsistent combination fails with one message naming the file, the key
// (e.g. "imu.rate_hz", "faults[1].params.std_ms") and the allowed range or values.
bool loadScenario(const std::string& path, Scenario* out, std::string* error);

// Same, from YAML text; `source_name` stands for the file name in messages.
bool parseScenario(const std::string& yaml_text, const std::string& source_name, Scenario* out,
                   std::string* error);

}  // namespace deepnav::sim
