#include "viewer/panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "image/tone_map.h"
#include "render/heat_map.h"
#include "settings/integrators.h"
#include "settings/setting_table.h"
#include "viewer/camera_controller.h"

namespace fp {

const char* const kViewerControlsHelp =
    "left drag        orbit around the target\n"
    "middle drag      pan (or shift + left drag)\n"
    "right drag       look around\n"
    "wheel            dolly toward / away from the target\n"
    "ctrl + click     focus on the surface under the cursor\n"
    "                 (depth of field: set an aperture under camera)\n"
    "F                fly mode: W/A/S/D move, Q/E down/up,\n"
    "                 the mouse looks; F or Esc leaves\n"
    "R                reset to the scene's camera\n"
    "N                show the raw or the denoised image\n"
    "P                screenshot: fragpath_<N>spp.png (as shown)\n"
    "                 and .exr (linear), in the current directory\n"
    "H                hide / show this panel\n";

namespace {

const char* const kToneMaps[] = {"clamp", "reinhard", "aces"};
const char* const kDenoisers[] = {"none", "bilateral", "atrous"};
const char* const kRealtimeViews[] = {"image", "history length", "deviation", "disocclusion"};
const int kFpsChoices[] = {15, 30, 60};
const float kScales[] = {1.0f, 0.5f, 0.25f, 0.125f};
const char* const kScaleNames[] = {"full", "1/2", "1/4", "1/8"};
// The panel covers about a quarter of an 800x600 window with the default sections open.
constexpr float kDefaultPanelWidth = 272.0f, kMinPanelWidth = 200.0f;
constexpr float kLabelWidth = 84.0f;  // right of the widgets: "integrator", "resolution", "target spp"

// What a count view counts, for the legend.
const char* countUnit(View view) {
    switch (view) {
        case View::Bounces:
            return "bounces survived";
        case View::Nodes:
            return "BVH nodes visited";
        case View::Triangles:
            return "triangles tested";
        default:
            return "";
    }
}

// A row of the settings table (settings/setting_table.h) as a widget: a combo box for a choice, else a
// number field kept in the row's range; its help is the tooltip.
bool settingWidget(const Setting& setting, double& value, const std::string& label) {
    bool changed = false;
    if (setting.kind == SettingKind::Choice) {
        if (ImGui::BeginCombo(label.c_str(), settingText(setting, value).c_str())) {
            for (const SettingChoice& choice : setting.choices)
                if (ImGui::Selectable(choice.name, choice.value == value) && choice.value != value) {
                    value = choice.value;
                    changed = true;
                }
            ImGui::EndCombo();
        }
    } else if (setting.kind == SettingKind::Integer) {
        int v = int(value);
        changed = ImGui::InputInt(label.c_str(), &v);
        if (changed) value = std::clamp(double(v), setting.min, setting.max);
    } else {
        float v = float(value);
        changed = ImGui::InputFloat(label.c_str(), &v, 0.0f, 0.0f, "%.3g");
        if (changed) value = std::isfinite(v) ? std::clamp(double(v), setting.min, setting.max) : value;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", setting.help);
    return changed;
}

// "max_depth" -> "max depth", and an ImGui id suffix to tell two widgets of one setting apart.
std::string settingLabel(const Setting& setting, const char* id = "") {
    std::string label = setting.name;
    std::replace(label.begin(), label.end(), '_', ' ');
    return label + id;
}

// The settings of `options` (RequestOption bits, in that order) that the integrator honours; the panel
// has its own controls for size, target spp and samples per frame. A setting the integrator ignores is
// hidden and set back to its default (bdpt refuses a clamp).
void settingWidgets(RenderSettings& render, std::initializer_list<unsigned> options) {
    for (unsigned option : options)
        for (const Setting& setting : settingTable()) {
            if (setting.option != option || setting.hidden || setting.option == kSizeOption ||
                setting.option == kSppOption || std::string(setting.name) == "samples_per_pass")
                continue;
            double value = setting.get(render);
            if (!integratorHonours(render.integrator, setting))
                value = settingDefault(setting);
            else
                settingWidget(setting, value, settingLabel(setting));
            setting.set(render, value);
        }
}

// The heat map's colours from 0 to max, as the display pass draws them.
void heatLegend(View view, float heatMax) {
    ImDrawList* draw = ImGui::GetWindowDrawList();
    ImVec2 origin = ImGui::GetCursorScreenPos();
    float width = ImGui::GetContentRegionAvail().x, height = 14.0f;
    const int segments = int(kHeatMapStops.size()) - 1;
    for (int i = 0; i < segments; ++i) {
        glm::vec3 a = kHeatMapStops[size_t(i)], b = kHeatMapStops[size_t(i) + 1];
        ImU32 left = ImGui::GetColorU32(ImVec4(a.r, a.g, a.b, 1.0f));
        ImU32 right = ImGui::GetColorU32(ImVec4(b.r, b.g, b.b, 1.0f));
        float x0 = origin.x + width * float(i) / float(segments);
        float x1 = origin.x + width * float(i + 1) / float(segments);
        draw->AddRectFilledMultiColor(ImVec2(x0, origin.y), ImVec2(x1, origin.y + height), left, right, right,
                                      left);
    }
    ImGui::Dummy(ImVec2(width, height));
    char top[32];
    std::snprintf(top, sizeof top, "%g", double(heatMax));
    ImGui::TextUnformatted("0");
    ImGui::SameLine(std::max(0.0f, width - ImGui::CalcTextSize(top).x));
    ImGui::TextUnformatted(top);
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%s per primary ray (mean)", countUnit(view));
    ImGui::PopStyleColor();
}

// 3 significant digits and a k, M or G suffix: 448k, 12.5M (the panel is narrow).
std::string shortNumber(double value) {
    const char* suffix = "";
    for (const char* s : {"k", "M", "G"}) {
        if (!(std::abs(value) >= 999.5)) break;
        value /= 1000.0;
        suffix = s;
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.3g%s", value, suffix);
    return text;
}

void statistics(const ViewerControls& c, const PanelInfo& info) {
    if (c.realtime) {
        ImGui::Text("real-time %d spp/frame at %.0f %% of the pixels, target %d fps", info.realtimeSpp,
                    100.0 * double(info.realtimeScale * info.realtimeScale), c.targetFps);
        ImGui::Text("image    %d x %d", info.accumulation.x, info.accumulation.y);
        ImGui::Text("frame    %.1f ms", info.frameMs);
        ImGui::Text("trace %.1f  temporal %.1f  filter %.1f ms", info.traceMs, info.temporalMs,
                    info.filterMs);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("the last frame's stages, each to glFinish; the rest is panel and display");
        return;
    }
    if (c.targetSpp > 0)
        ImGui::Text("samples  %d / %d%s", info.samples, c.targetSpp,
                    info.samples >= c.targetSpp ? " (done)" : "");
    else
        ImGui::Text("samples  %d", info.samples);
    ImGui::Text("image    %d x %d%s", info.accumulation.x, info.accumulation.y,
                info.reduced ? " (moving)" : "");
    if (ImGui::IsItemHovered() && info.reduced)
        ImGui::SetTooltip("a reduced resolution while the camera moves");
    ImGui::Text("speed    %.3g spp/s, %s paths/s", info.samplesPerSecond,
                shortNumber(info.pathsPerSecond).c_str());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("samples per pixel per second, paths per second");
    ImGui::Text("frame    %.1f ms", info.frameMs);
    if (info.denoiseMs > 0.0) {
        ImGui::Text("denoise  %.1f ms", info.denoiseMs);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("the last denoising run; at most 1/4 of the time");
    }
}

// The essentials: what is rendered, and until when.
void renderSettings(ViewerControls& c) {
    settingWidgets(c.render, {kIntegratorOption, kPathOptions, kViewOption});
    ImGui::InputInt("target spp", &c.targetSpp);
    c.targetSpp = std::max(c.targetSpp, 0);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("stop rendering at this many samples per pixel; 0: never");
}

void samplingSettings(ViewerControls& c) {
    settingWidgets(c.render, {kSamplingOptions});
    int scale = 0;
    for (size_t i = 0; i < std::size(kScales); ++i)
        if (kScales[i] == c.resolutionScale) scale = int(i);
    if (ImGui::Combo("resolution", &scale, kScaleNames, int(std::size(kScaleNames))))
        c.resolutionScale = kScales[scale];
}

// Real-time mode: a few samples per frame, reprojected history and a filter (SVGF's scheme).
void realtimeSettings(ViewerControls& c, const PanelInfo& info) {
    ImGui::Checkbox("real-time", &c.realtime);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "trace a few samples per pixel each frame at the current camera, reuse the history\n"
            "reprojected from earlier frames and filter it; off: progressive accumulation");
    if (!c.realtime) return;
    int fps = 1;
    for (size_t i = 0; i < std::size(kFpsChoices); ++i)
        if (kFpsChoices[i] == c.targetFps) fps = int(i);
    if (ImGui::SliderInt("target fps", &fps, 0, int(std::size(kFpsChoices)) - 1,
                         std::to_string(kFpsChoices[fps]).c_str()))
        c.targetFps = kFpsChoices[fps];
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("samples per frame adapt to fit 1000 / fps ms");
    ImGui::Checkbox("temporal reuse", &c.temporalReuse);
    ImGui::SameLine();
    ImGui::Checkbox("filter", &c.realtimeFilter);
    ImGui::Checkbox("dynamic resolution", &c.dynamicResolution);
    ImGui::Combo("debug view", &c.realtimeView, kRealtimeViews, int(std::size(kRealtimeViews)));
    c.realtimeView = std::clamp(c.realtimeView, 0, int(std::size(kRealtimeViews)) - 1);
    if (c.realtimeView == 1)
        ImGui::TextDisabled("heat map: 0 to %.0f frames", double(info.historyMaxFrames));
    else if (c.realtimeView == 2)
        ImGui::TextDisabled("heat map: the filter's deviation, 0 to 1");
    else if (c.realtimeView == 3)
        ImGui::TextDisabled("heat map: 1 where the history was rejected");
}

void splitSettings(ViewerControls& c) {
    ImGui::Checkbox("split the view", &c.split);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("the right half uses another integrator or depth, at the same sample count");
    if (c.split) {
        const Setting &integrator = *findSetting("integrator"), &depth = *findSetting("max_depth");
        double i = double(int(c.splitView.integrator)), d = c.splitView.maxDepth;
        if (settingWidget(integrator, i, settingLabel(integrator, "##right")))
            c.splitView.integrator = Integrator(int(i));
        if (settingWidget(depth, d, settingLabel(depth, "##right"))) c.splitView.maxDepth = int(d);
    }
}

bool displaySettings(ViewerControls& c) {
    bool fit = false;
    int denoiser = int(c.denoiser);
    if (ImGui::Combo("denoiser", &denoiser, kDenoisers, int(std::size(kDenoisers))))
        c.denoiser = Denoiser(denoiser);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "bilateral: joint bilateral filter; atrous: edge-avoiding a-trous wavelets steered by\n"
            "the per-pixel variance (SVGF's spatial filter). Radiance view only; restarts once.");
    if (c.denoiser != Denoiser::None) ImGui::Checkbox("show denoised (N)", &c.showDenoised);
    if (isCountView(c.render.view)) {
        ImGui::Checkbox("auto range", &c.autoHeatMax);
        ImGui::SameLine();
        fit = ImGui::Button("fit now");
        if (ImGui::DragFloat("heat max", &c.heatMax, 0.1f, 0.1f, 1e6f, "%.1f")) c.autoHeatMax = false;
        c.heatMax = std::max(c.heatMax, 0.1f);
        heatLegend(c.render.view, c.heatMax);
    } else {
        ImGui::SliderFloat("exposure", &c.tone.exposure, -8.0f, 8.0f, "%.1f stops");
        int toneMap = int(c.tone.toneMap);
        if (ImGui::Combo("tone map", &toneMap, kToneMaps, int(std::size(kToneMaps))))
            c.tone.toneMap = ToneMap(toneMap);
    }
    return fit;
}

void cameraSettings(const PanelInfo& info, PanelActions& actions) {
    float fov = info.camera.fovY;
    if (ImGui::SliderFloat("fov", &fov, CameraController::kMinFovDegrees, CameraController::kMaxFovDegrees,
                           "%.1f deg"))
        actions.fov = fov;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("vertical field of view");
    bool flying = info.flying;
    if (ImGui::Checkbox("fly mode (F)", &flying)) actions.toggleFly = true;
    ImGui::SameLine();
    actions.resetCamera = ImGui::Button("reset (R)");
    const Camera& cam = info.camera;
    // The thin lens. Scene units differ from scene to scene: the drags move by a small part of the focus
    // distance per pixel.
    const Camera& lens = info.camera;
    float focus = resolvedFocusDistance(lens);
    float aperture = lens.aperture;
    float step = std::max(1e-6f, 0.002f * focus);
    if (ImGui::DragFloat("aperture", &aperture, step, 0.0f, 1e30f, "%.4g"))
        actions.aperture = std::max(aperture, 0.0f);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("the lens diameter in scene units (depth of field); 0: a pinhole, all sharp");
    if (ImGui::DragFloat("focus", &focus, 4.0f * step, 0.0f, 1e30f, "%.4g") && focus > 0.0f)
        actions.focusDistance = focus;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "the distance to the plane in focus, along the view; ctrl + click on the image\n"
            "focuses on the surface under the cursor");
    if (lens.focusDistance) {
        actions.focusOnTarget = ImGui::Button("focus on the target");
    } else {
        ImGui::TextDisabled("focus follows the target");
    }
    ImGui::TextDisabled("eye    %.3g, %.3g, %.3g", double(cam.eye.x), double(cam.eye.y), double(cam.eye.z));
    ImGui::TextDisabled("target %.3g, %.3g, %.3g", double(cam.target.x), double(cam.target.y),
                        double(cam.target.z));
}

// The scene's punctual lights, which only nee and bdpt see.
void lightList(const ViewerControls& c, const PanelInfo& info) {
    for (const std::string& line : info.lights) {
        ImGui::Bullet();
        ImGui::TextWrapped("%s", line.c_str());  // the panel is narrow: wrap rather than cut
    }
    auto blind = [](Integrator i) { return i == Integrator::Naive || i == Integrator::Bsdf; };
    if (blind(c.render.integrator) || (c.split && blind(c.splitView.integrator))) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextWrapped(
            "naive and bsdf cannot see these lights (no ray hits a light of no size): use nee or bdpt");
        ImGui::PopStyleColor();
    }
}

// kViewerControlsHelp as a table whose descriptions wrap to the panel's width: a line that starts with
// spaces continues the description above it.
void controlsHelp() {
    constexpr size_t kKeyColumn = 17;  // where kViewerControlsHelp's descriptions start
    std::vector<std::pair<std::string, std::string>> rows;
    std::string text = kViewerControlsHelp;
    for (size_t start = 0; start < text.size();) {
        size_t end = std::min(text.find('\n', start), text.size());
        std::string line = text.substr(start, end - start);
        start = end + 1;
        std::string key = line.substr(0, std::min(kKeyColumn, line.size()));
        std::string what = line.size() > kKeyColumn ? line.substr(kKeyColumn) : "";
        key.erase(key.find_last_not_of(' ') + 1);
        if (key.empty() && !rows.empty())
            rows.back().second += " " + what;
        else
            rows.emplace_back(key, what);
    }
    if (!ImGui::BeginTable("controls", 2)) return;
    ImGui::TableSetupColumn("key", ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn("what", ImGuiTableColumnFlags_WidthStretch);
    for (const auto& [key, what] : rows) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(key.c_str());
        ImGui::TableNextColumn();
        ImGui::TextWrapped("%s", what.c_str());
    }
    ImGui::EndTable();
}

}  // namespace

PanelActions Panel::draw(ViewerControls& c, const PanelInfo& info) {
    PanelActions actions;
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    // Narrow at first (0: ImGui fits the first frames' height), as tall as its contents (they change:
    // open sections, split view, errors) but never taller than the window, where it scrolls. The user
    // may drag an edge to change the width, and collapse the panel by its title. Not AlwaysAutoResize,
    // nor a height set every frame: either would stop ImGui from resizing the window by hand.
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowSize(ImVec2(kDefaultPanelWidth, 0.0f), ImGuiCond_FirstUseEver);
    float maxHeight = std::max(display.y - 16.0f, 100.0f);
    heightWanted_ = std::min(contentHeight_, maxHeight);
    ImGui::SetNextWindowSizeConstraints(
        ImVec2(kMinPanelWidth, 0.0f), ImVec2(std::max(display.x - 16.0f, kMinPanelWidth), maxHeight),
        [](ImGuiSizeCallbackData* data) {
            float height = *static_cast<const float*>(data->UserData);
            if (height > 0.0f) data->DesiredSize.y = height;
        },
        &heightWanted_);
    ImGui::SetNextWindowBgAlpha(0.8f);
    if (!ImGui::Begin("fragpath")) {
        ImGui::End();
        return actions;
    }
    ImGui::PushItemWidth(-kLabelWidth);  // room for the labels
    statistics(c, info);
    // Right below the figures, where it cannot be missed or scrolled away.
    if (!info.shaderError.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.35f, 1.0f));
        ImGui::PushTextWrapPos(0.0f);  // TextUnformatted: no length limit for a long compiler log
        ImGui::TextUnformatted("shader error; the last shaders that compiled keep running:");
        ImGui::TextUnformatted(info.shaderError.c_str());
        ImGui::PopTextWrapPos();
        ImGui::PopStyleColor();
    }
    // The essentials open, the rest collapsed (ImGui remembers what the user opens). A split view asked
    // for on the command line opens its section.
    if (ImGui::CollapsingHeader("render", ImGuiTreeNodeFlags_DefaultOpen)) renderSettings(c);
    if (ImGui::CollapsingHeader("display", ImGuiTreeNodeFlags_DefaultOpen))
        actions.fitHeatMap = displaySettings(c);
    if (ImGui::CollapsingHeader("real-time", c.realtime ? ImGuiTreeNodeFlags_DefaultOpen : 0))
        realtimeSettings(c, info);
    if (ImGui::CollapsingHeader("sampling")) samplingSettings(c);
    if (ImGui::CollapsingHeader("split view", c.split ? ImGuiTreeNodeFlags_DefaultOpen : 0)) splitSettings(c);
    if (ImGui::CollapsingHeader("camera")) cameraSettings(info, actions);
    if (!info.lights.empty() && ImGui::CollapsingHeader("lights", ImGuiTreeNodeFlags_DefaultOpen))
        lightList(c, info);
    if (ImGui::CollapsingHeader("renderer")) {
        ImGui::TextWrapped("%s", info.renderer.c_str());
        ImGui::TextWrapped("shaders: %s", info.shaderSource.c_str());
    }
    if (ImGui::CollapsingHeader("help")) controlsHelp();
    actions.screenshot = ImGui::Button("screenshot (P)");
    if (!info.message.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextWrapped("%s", info.message.c_str());
        ImGui::PopStyleColor();
    }
    ImGui::PopItemWidth();
    // The window's height for these contents (the cursor's position is independent of the scrolling).
    contentHeight_ =
        ImGui::GetCursorPosY() - ImGui::GetStyle().ItemSpacing.y + ImGui::GetStyle().WindowPadding.y;
    ImGui::End();
    return actions;
}

}  // namespace fp
