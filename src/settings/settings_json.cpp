#include "settings/settings_json.h"

#include "settings/setting_table.h"

namespace fp {

nlohmann::json settingsJson(const RenderSettings& settings) {
    nlohmann::json j = nlohmann::json::object();
    for (const Setting& s : settingTable()) {
        const double value = s.get(settings);
        if (s.kind == SettingKind::Choice || (s.specialName && value == s.specialValue))
            j[s.name] = settingText(s, value);
        else if (s.kind == SettingKind::Integer)
            j[s.name] = (long long)value;
        else
            j[s.name] = value;
    }
    return j;
}

}  // namespace fp
