#include "settings/setting_table.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <type_traits>

#include "core/error.h"
#include "core/text.h"
#include "settings/integrators.h"

namespace fp {

namespace {

// A row's accessors, from the RenderSettings member they read and write.
template <auto Member>
double getMember(const RenderSettings& s) {
    using T = std::remove_reference_t<decltype(s.*Member)>;
    if constexpr (std::is_enum_v<T>)
        return double(static_cast<int>(s.*Member));
    else
        return double(s.*Member);
}

template <auto Member>
void setMember(RenderSettings& s, double value) {
    using T = std::remove_reference_t<decltype(s.*Member)>;
    if constexpr (std::is_enum_v<T>)
        s.*Member = static_cast<T>(int(value));
    else
        s.*Member = static_cast<T>(value);
}

template <typename E, size_t N>
std::vector<SettingChoice> choicesOf(const E (&all)[N], const char* (*name)(E)) {
    std::vector<SettingChoice> choices;
    for (E e : all) choices.push_back({name(e), int(e)});
    return choices;
}

// "naive: uniform hemisphere sampling | bsdf: ...": --integrator's help, from the integrators' facts.
const char* integratorSummaries() {
    static const std::string text = [] {
        std::string lines;
        for (Integrator i : kAllIntegrators) {
            const IntegratorFacts& facts = integratorFacts(i);
            lines += (lines.empty() ? "" : "\n") + std::string(facts.name) + ": " + facts.summary;
            if (facts.depthCap > 0) lines += ", at most " + std::to_string(facts.depthCap) + " bounces";
        }
        return lines;
    }();
    return text.c_str();
}

constexpr double kUnbounded = std::numeric_limits<double>::infinity();
constexpr unsigned kShaderSetting = kRestartsAccumulation | kRecompiles | kEntersFingerprint;

std::vector<Setting> makeTable() {
    using R = RenderSettings;
    // clang-format off
    return {
        // Image. Width and height share --size WxH.
        {"width", "--size", "WxH", kSizeOption, SettingKind::Integer, {}, 1, 65536, nullptr, 0,
         "image size", "uniform uResolution", kRestartsAccumulation | kEntersFingerprint, true, false,
         getMember<&R::width>, setMember<&R::width>},
        {"height", "--size", "WxH", kSizeOption, SettingKind::Integer, {}, 1, 65536, nullptr, 0,
         "image size", "uniform uResolution", kRestartsAccumulation | kEntersFingerprint, true, false,
         getMember<&R::height>, setMember<&R::height>},
        {"spp", "--spp", "N", kSppOption, SettingKind::Integer, {}, 1, 1 << 24, "unlimited", 0,
         "samples per pixel; unlimited: until stopped (an interrupted render writes its image)", "none: the front end stops there", 0,
         true, false, getMember<&R::spp>, setMember<&R::spp>},
        // Path tracing.
        {"max_depth", "--max-depth", "D", kPathOptions, SettingKind::Integer, {}, 0, 1000, nullptr, 0,
         "bounces: 0 shows emitters only, 1 direct light, ...", "uniform uMaxDepth",
         kRestartsAccumulation | kEntersFingerprint, true, false, getMember<&R::maxDepth>,
         setMember<&R::maxDepth>},
        {"seed", "--seed", "S", kPathOptions, SettingKind::Integer, {}, 0, double(kMaxSeed), nullptr, 0,
         "random seed; the same seed gives the same image bit for bit", "uniform uSeed",
         kRestartsAccumulation | kEntersFingerprint, true, false, getMember<&R::seed>, setMember<&R::seed>},
        {"integrator", "--integrator", "NAME", kIntegratorOption, SettingKind::Choice,
         choicesOf(kAllIntegrators, integratorName), 0, 0, nullptr, 0, integratorSummaries(),
         "define INTEGRATOR_FILE (glsl/integrators/NAME.glsl)", kShaderSetting, true, false,
         getMember<&R::integrator>, setMember<&R::integrator>},
        {"sampler", "--sampler", "NAME", kSamplingOptions, SettingKind::Choice,
         choicesOf(kAllSamplers, samplerName), 0, 0, nullptr, 0,
         "sobol: Owen-scrambled Sobol points, blue noise over the screen |\nindependent: independent "
         "uniform numbers", "define SAMPLER", kShaderSetting, true, false, getMember<&R::sampler>,
         setMember<&R::sampler>},
        {"light_sampling", "--light-sampling", "NAME", kSamplingOptions, SettingKind::Choice,
         choicesOf(kAllLightSamplings, lightSamplingName), 0, 0, nullptr, 0,
         "auto: solid angle when an emitter faces a close surface | area |\nsolid-angle (nee: emitters "
         "over 0.1 sr by solid angle)", "define SPHERICAL_LIGHT_SAMPLING", kShaderSetting, true, false,
         getMember<&R::lightSampling>, setMember<&R::lightSampling>},
        {"light_selection", "--light-selection", "NAME", kSamplingOptions, SettingKind::Choice,
         choicesOf(kAllLightSelections, lightSelectionName), 0, 0, nullptr, 0,
         "auto: the tree for scenes of many emitters | power: by power |\ntree: by a light tree, power "
         "weighed by distance and orientation (nee)", "define LIGHT_TREE",
         kRestartsAccumulation | kRecompiles | kEntersFingerprintIfChosen, true, false,
         getMember<&R::lightSelection>, setMember<&R::lightSelection>},
        {"caustics", "--caustics", "NAME", kSamplingOptions, SettingKind::Choice,
         choicesOf(kAllCaustics, causticsName), 0, 0, nullptr, 0,
         "auto: light where glass, mirrors or glossy metals meet a light | path:\ncamera paths alone | "
         "light: light paths traced to glass, mirrors and\nglossy metals, joined to the camera (nee)",
         "define CAUSTICS_LIGHT_TRACED", kRestartsAccumulation | kRecompiles | kEntersFingerprintIfChosen,
         true, false, getMember<&R::caustics>, setMember<&R::caustics>},
        {"clamp_indirect", "--clamp-indirect", "X", kSamplingOptions, SettingKind::Number, {}, 0,
         kUnbounded, nullptr, 0,
         "scale each sample's indirect light down to at most X per channel:\nfewer fireflies, but BIASED "
         "(darker); 0: off; not with bdpt",
         "uniform uClampIndirect (and caustics auto: path)", kShaderSetting, true, false,
         getMember<&R::clampIndirect>, setMember<&R::clampIndirect>},
        {"samples_per_pass", "--samples-per-pass", "N", kSamplingOptions, SettingKind::Integer, {}, 1,
         R::kMaxSamplesPerPass, "auto", R::kAutoSamplesPerPass,
         "samples each pixel takes per draw call; auto: as many as fit a\nsecond; the image is the same",
         "uniform uSamplesPerPass", kRestartsAccumulation, false, false, getMember<&R::samplesPerPass>,
         setMember<&R::samplesPerPass>},
        // Display.
        {"view", "--view", "NAME", kViewOption, SettingKind::Choice, choicesOf(kAllViews, viewName), 0, 0,
         nullptr, 0,
         "depth, normal, albedo: of the first hit | bounces, nodes, triangles:\nper primary ray, as a "
         "heat map | cost: nodes, triangles, surfaces per\npath in R, G, B",
         "define DEBUG_VIEW", kShaderSetting, false, false, getMember<&R::view>, setMember<&R::view>},
        // Set by front ends, not by a flag of their own: render's --sample-offset and --denoise.
        {"sample_offset", "", "", 0, SettingKind::Integer, {}, 0, double(1u << 30), nullptr, 0,
         "the first sample's index (one range of a larger render)", "uniform uSampleOffset",
         kRestartsAccumulation, false, true, getMember<&R::sampleOffset>, setMember<&R::sampleOffset>},
        {"guides", "", "", 0, SettingKind::Integer, {}, 0, 1, nullptr, 0,
         "also accumulate the first hit's normal, depth and albedo (the denoisers' guides)",
         "define GUIDES", kRestartsAccumulation | kRecompiles, false, true, getMember<&R::guides>,
         setMember<&R::guides>},
    };
    // clang-format on
}

std::string numberText(double value) {
    if (value == std::floor(value) && std::abs(value) < 1e15) return std::to_string((long long)value);
    return formatText("%g", value);
}

std::vector<std::string> choiceNameList(const Setting& s) {
    std::vector<std::string> names;
    for (const SettingChoice& c : s.choices) names.push_back(c.name);
    return names;
}

}  // namespace

const std::vector<Setting>& settingTable() {
    static const std::vector<Setting> table = makeTable();
    return table;
}

const Setting* findSetting(const std::string& name) {
    for (const Setting& s : settingTable())
        if (name == s.name) return &s;
    return nullptr;
}

std::string settingChoices(const Setting& s) {
    switch (s.kind) {
        case SettingKind::Choice: {
            std::string text;
            for (const std::string& name : choiceNameList(s)) text += (text.empty() ? "" : " | ") + name;
            return text;
        }
        case SettingKind::Integer:
        case SettingKind::Number: {
            std::string range = s.max == kUnbounded ? numberText(s.min) + " or more"
                                                    : numberText(s.min) + " to " + numberText(s.max);
            return s.specialName ? range + ", or " + s.specialName : range;
        }
    }
    return "";
}

void refuseSetting(const Setting& s, const std::string& got, const std::string& where) {
    const std::string what = s.kind == SettingKind::Choice
                                 ? "one of " + choiceList(choiceNameList(s))
                                 : (s.kind == SettingKind::Integer ? "a whole number" : "a number") +
                                       std::string(s.max == kUnbounded ? ", " : " from ") + settingChoices(s);
    throw Error(where + " must be " + what + ", got " + got);
}

// Whether `value` is one of the row's choices or in its range (its special value aside).
static bool inRow(const Setting& s, double value) {
    bool ok = false;
    switch (s.kind) {
        case SettingKind::Choice:
            for (const SettingChoice& c : s.choices) ok = ok || value == c.value;
            break;
        case SettingKind::Integer:
            ok = value >= s.min && value <= s.max && value == std::floor(value);
            break;
        case SettingKind::Number:
            ok = value >= s.min && value <= s.max && std::isfinite(value);
            break;
    }
    return ok;
}

double checkSetting(const Setting& s, double value, const std::string& where) {
    if (!inRow(s, value)) refuseSetting(s, formatText("%.10g", value), where);
    return value;
}

double parseSetting(const Setting& s, const std::string& text, const std::string& where) {
    if (s.specialName && text == s.specialName) return s.specialValue;
    if (s.kind == SettingKind::Choice) {
        for (const SettingChoice& c : s.choices)
            if (text == c.name) return c.value;
        std::string what = s.name;
        std::replace(what.begin(), what.end(), '_', ' ');
        throw Error(where + ": unknown " + what + " '" + text + "' (choose " + choiceList(choiceNameList(s)) +
                    ")");
    }
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !inRow(s, value))
        refuseSetting(s, "'" + text + "'", where);
    return value;
}

std::string settingText(const Setting& s, double value) {
    if (s.specialName && value == s.specialValue) return s.specialName;
    if (s.kind == SettingKind::Choice)
        for (const SettingChoice& c : s.choices)
            if (value == c.value) return c.name;
    return numberText(value);
}

double settingDefault(const Setting& s) {
    return s.get(RenderSettings());
}

SettingValues::SettingValues() : values_(settingTable().size()) {}

static size_t rowOf(const Setting& setting) {
    return size_t(&setting - settingTable().data());
}

void SettingValues::set(const Setting& setting, double value) {
    values_.at(rowOf(setting)) = value;
}

void SettingValues::set(const std::string& name, double value) {
    const Setting* s = findSetting(name);
    if (!s) throw Error("no setting named '" + name + "'");
    set(*s, value);
}

std::optional<double> SettingValues::get(const Setting& setting) const {
    return values_.at(rowOf(setting));
}

std::optional<double> SettingValues::get(const std::string& name) const {
    const Setting* s = findSetting(name);
    if (!s) throw Error("no setting named '" + name + "'");
    return get(*s);
}

bool SettingValues::empty() const {
    for (const auto& v : values_)
        if (v) return false;
    return true;
}

void SettingValues::applyTo(RenderSettings& settings) const {
    for (const Setting& s : settingTable())
        if (auto v = get(s)) s.set(settings, *v);
}

bool sameSettings(const RenderSettings& a, const RenderSettings& b, unsigned effects) {
    for (const Setting& s : settingTable())
        if ((s.effects & effects) && s.get(a) != s.get(b)) return false;
    return true;
}

void checkSettings(const RenderSettings& settings) {
    for (const Setting& s : settingTable()) {
        const double value = s.get(settings);
        if (!(s.specialName && value == s.specialValue))
            checkSetting(s, value, std::string("setting ") + s.name);
    }
}

}  // namespace fp
