#pragma once
// THE SETTINGS TABLE: every render setting declared once, as data. Per setting: its name (the scene
// file's key under "render" and the JSON outputs' key), its command-line flag, its kind with choices or
// range, its help text, where it reaches the shader, and what changing it does. Parsing the command line
// and the scene file, merging them, --help, the fingerprint of a partial render, the viewer's
// accumulation and recompile checks, the JSON outputs and the viewer's panel are loops over it.
//
// The default is RenderSettings' own (settings/render_settings.h); a front end may replace some
// (request/render_request.h FrontEndDefaults). Values travel as doubles: an integer, a number, or a
// choice's enumerator.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "settings/render_settings.h"

namespace fp {

// The shared options, as bits: a front end takes the ones that mean something to it. The settings'
// rows name theirs; the others are read by RenderRequest itself.
enum RequestOption : unsigned {
    kSizeOption = 1u << 0,        // --size WxH
    kSppOption = 1u << 1,         // --spp N
    kIntegratorOption = 1u << 2,  // --integrator NAME
    kPathOptions = 1u << 3,       // --max-depth D, --seed S
    kSamplingOptions = 1u << 4,   // --sampler, --light-sampling, --light-selection, --caustics,
                                  // --clamp-indirect, --samples-per-pass
    kCameraOptions = 1u << 5,     // --eye, --target, --up, --fov, --aperture, --focus-distance
    kViewOption = 1u << 6,        // --view NAME
    kDisplayOptions = 1u << 7,    // --exposure, --tonemap
    kShaderOptions = 1u << 8,     // --shader-dir, --bvh-threads
    kBackendOption = 1u << 9,     // --backend NAME
    kSceneOptions = 1u << 10,     // --environment ENV, --strict, --flatten-instances
};
constexpr unsigned kAllRequestOptions = (1u << 11) - 1;

enum class SettingKind { Integer, Number, Choice };

// What a change of the setting does.
enum SettingEffect : unsigned {
    kRestartsAccumulation = 1u << 0,  // the samples so far no longer add up to one image
    kRecompiles = 1u << 1,            // it is a define: the shaders are compiled again
    kEntersFingerprint = 1u << 2,     // parts rendered with other values do not merge
    // Enters the fingerprint only when not the default: a setting added after renders were saved leaves
    // their fingerprints as they were, so that they still resume and merge.
    kEntersFingerprintIfChosen = 1u << 3,
};

struct SettingChoice {
    const char* name;
    int value;  // the enumerator
};

struct Setting {
    const char* name;       // "max_depth"
    const char* flag;       // "--max-depth"; "" when only a front end sets it (a viewer's split, --denoise)
    const char* valueName;  // "D" in the help
    unsigned option;        // the RequestOption bit a front end takes it by
    SettingKind kind;
    std::vector<SettingChoice> choices;  // SettingKind::Choice
    double min, max;                     // Integer and Number
    // A value outside [min, max] with a name of its own ("auto" for 0 samples per pass), or nullptr.
    const char* specialName;
    double specialValue;
    const char* help;    // '\n' starts another line; the default is appended
    const char* shader;  // where the shader sees it: "define SAMPLER", "uniform uMaxDepth", ...
    unsigned effects;    // SettingEffect bits
    bool sceneFile;      // a scene file's "render" block may set it
    bool hidden;         // tests and front ends set it; --help does not list it
    double (*get)(const RenderSettings&);
    void (*set)(RenderSettings&, double);
};

// Width and height share one flag, --size WxH (each row takes its part of the value).
inline bool isSizePart(const Setting& setting) {
    return std::string(setting.valueName) == "WxH";
}

// Every setting, in the order --help lists them (and the fingerprint hashes them).
const std::vector<Setting>& settingTable();
const Setting* findSetting(const std::string& name);  // by name; nullptr when there is none

// `text` read as the setting's value: a choice's name, a whole number or a number in range, or the
// special name. Throws fp::Error "<where>: ..." ("option --max-depth", "scene.json: render.max_depth").
double parseSetting(const Setting& setting, const std::string& text, const std::string& where);
// Checks a value that arrives as a number (a scene file's): a choice's enumerator or a number in range,
// not the special value, which is given by its name; throws as parseSetting does.
double checkSetting(const Setting& setting, double value, const std::string& where);
// Throws fp::Error "<where> must be a whole number from 1 to 65536, got <got>": the one message of a value
// out of range or of the wrong kind, from the command line or a scene file.
[[noreturn]] void refuseSetting(const Setting& setting, const std::string& got, const std::string& where);
// The value as the command line writes it: "nee", "5", "0.25", "auto".
std::string settingText(const Setting& setting, double value);
// "naive | bsdf | nee | bdpt", "0 to 1000", "1 to 16 or auto", "0 or more".
std::string settingChoices(const Setting& setting);
double settingDefault(const Setting& setting);  // RenderSettings' own

// Values for some of the settings, as a scene file or a command line gives them.
class SettingValues {
  public:
    SettingValues();
    void set(const Setting& setting, double value);
    void set(const std::string& name, double value);  // throws for a name not in the table
    std::optional<double> get(const Setting& setting) const;
    std::optional<double> get(const std::string& name) const;  // throws for a name not in the table
    bool empty() const;
    // Sets these values in `settings`, leaving the others.
    void applyTo(RenderSettings& settings) const;

  private:
    std::vector<std::optional<double>> values_;  // by row of settingTable()
};

// Whether `a` and `b` agree on every setting with any of the `effects` bits.
bool sameSettings(const RenderSettings& a, const RenderSettings& b, unsigned effects);

// Checks every setting of `settings` against its row (range, choice); throws fp::Error naming the
// setting. What the renderer checks before it renders.
void checkSettings(const RenderSettings& settings);

}  // namespace fp
