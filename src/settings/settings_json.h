#pragma once
// The settings as JSON, one key a row of the settings table (settings/setting_table.h): what --json,
// the benchmark's JSON and the study's outputs record of a render.
#include <nlohmann/json.hpp>

#include "settings/render_settings.h"

namespace fp {

// {"width": 512, ..., "integrator": "nee", "samples_per_pass": "auto", ...}: choices and special values
// by name, numbers as numbers.
nlohmann::json settingsJson(const RenderSettings& settings);

}  // namespace fp
