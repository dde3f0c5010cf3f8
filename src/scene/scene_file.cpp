#include "scene/scene_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/log.h"
#include "core/text.h"
#include "image/image.h"
#include "scene/lighting.h"
#include "scene/load.h"
#include "scene/punctual_light.h"
#include "scene/text_file.h"

namespace fp {

namespace {

using nlohmann::json;

// Reads values out of the parsed JSON, naming the file and the key path ("camera.fov") in errors.
class Fields {
  public:
    explicit Fields(const std::string& name) : name_(name) {}

    [[noreturn]] void fail(const std::string& message) const { throw Error(name_ + ": " + message); }

    // Collects keys of `object` that are not `known`, for one warning at the end: typos like "fov_y"
    // would otherwise be silently ignored.
    void checkKeys(const json& object, const std::string& prefix, std::initializer_list<const char*> known) {
        checkKeys(object, prefix, std::vector<const char*>(known));
    }
    void checkKeys(const json& object, const std::string& prefix, const std::vector<const char*>& known) {
        for (const auto& item : object.items()) {
            bool found =
                std::any_of(known.begin(), known.end(), [&](const char* k) { return item.key() == k; });
            if (!found) unknown_.push_back("'" + prefix + item.key() + "'");
        }
    }
    void warnUnknownKeys() const {
        if (unknown_.empty()) return;
        std::string list;
        for (const std::string& k : unknown_) list += (list.empty() ? "" : ", ") + k;
        warn(name_ + ": ignoring unknown key" + (unknown_.size() == 1 ? " " : "s ") + list);
    }

    const json& object(const json& value, const std::string& path) const {
        if (!value.is_object()) fail(path + " must be a JSON object, got " + shown(value));
        return value;
    }

    std::string string(const json& value, const std::string& path) const {
        if (!value.is_string()) fail(path + " must be a string, got " + shown(value));
        return value.get<std::string>();
    }

    // A finite number that stays finite as a float.
    float real(const json& value, const std::string& path) const {
        if (!value.is_number()) fail(path + " must be a number, got " + shown(value));
        double d = value.get<double>();
        if (!std::isfinite(static_cast<float>(d)))
            fail(path + " must be a finite number, got " + shown(value));
        return static_cast<float>(d);
    }

    const json& array(const json& value, const std::string& path, const std::string& what) const {
        if (!value.is_array()) fail(path + " must be an array of " + what + ", got " + shown(value));
        return value;
    }

    glm::vec3 vec3(const json& value, const std::string& path) const {
        if (!value.is_array() || value.size() != 3)
            fail(path + " must be an array of 3 numbers, got " + shown(value));
        glm::vec3 v;
        for (int i = 0; i < 3; ++i)
            v[i] = real(value[static_cast<size_t>(i)], path + "[" + std::to_string(i) + "]");
        return v;
    }

    // An integer in [lo, hi]; 512.0 counts as an integer, 512.5 does not.
    long long integer(const json& value, const std::string& path, long long lo, long long hi) const {
        std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
        if (value.is_number_unsigned()) {
            unsigned long long v = value.get<unsigned long long>();
            // nlohmann stores every non-negative integer (0 too) as unsigned.
            if (v > static_cast<unsigned long long>(hi) || static_cast<long long>(v) < lo)
                fail(path + " must be in " + range + ", got " + shown(value));
            return static_cast<long long>(v);
        }
        if (value.is_number_integer()) {
            long long v = value.get<long long>();
            if (v < lo || v > hi) fail(path + " must be in " + range + ", got " + shown(value));
            return v;
        }
        if (value.is_number_float()) {
            double d = value.get<double>();
            if (!std::isfinite(d) || d != std::floor(d))
                fail(path + " must be an integer, got " + shown(value));
            if (d < static_cast<double>(lo) || d > static_cast<double>(hi))
                fail(path + " must be in " + range + ", got " + shown(value));
            return static_cast<long long>(d);
        }
        fail(path + " must be an integer, got " + shown(value));
    }

    // The offending value as JSON, shortened for the message.
    static std::string shown(const json& value) {
        std::string text = value.dump(-1, ' ', false, json::error_handler_t::replace);
        return text.size() > 60 ? text.substr(0, 57) + "..." : text;
    }

  private:
    const std::string& name_;
    std::vector<std::string> unknown_;
};

// nlohmann's message without its "[json.exception.parse_error.101] " prefix; what remains says where
// ("parse error at line 3, column 5: ...").
std::string withoutId(const json::exception& e) {
    std::string what = e.what();
    size_t start = what.find("] ");
    return start == std::string::npos ? what : what.substr(start + 2);
}

Camera parseCamera(const json& camera, Fields& fields) {
    fields.object(camera, "camera");
    fields.checkKeys(camera, "camera.", {"eye", "target", "up", "fov", "aperture", "focus_distance"});
    bool hasEye = camera.contains("eye"), hasTarget = camera.contains("target");
    // Defaulting one of the two would put the camera somewhere the author did not choose.
    if (!hasEye || !hasTarget)
        fields.fail(std::string("camera needs both eye and target (") + (hasEye ? "target" : "eye") +
                    " is missing)");
    Camera c;
    c.eye = fields.vec3(camera["eye"], "camera.eye");
    c.target = fields.vec3(camera["target"], "camera.target");
    if (camera.contains("up")) c.up = fields.vec3(camera["up"], "camera.up");
    if (camera.contains("fov")) c.fovY = fields.real(camera["fov"], "camera.fov");
    if (camera.contains("aperture")) c.aperture = fields.real(camera["aperture"], "camera.aperture");
    if (camera.contains("focus_distance"))
        c.focusDistance = fields.real(camera["focus_distance"], "camera.focus_distance");

    try {
        validateCamera(c, "camera");
    } catch (const Error& e) {
        fields.fail(e.what());
    }
    return c;
}

// The "render" block: the settings table's rows that a scene file may set (settings/setting_table.h),
// by the same names, choices and ranges as on the command line.
SettingValues parseRender(const json& render, Fields& fields) {
    fields.object(render, "render");
    std::vector<const char*> keys;
    for (const Setting& s : settingTable())
        if (s.sceneFile) keys.push_back(s.name);
    fields.checkKeys(render, "render.", keys);
    SettingValues values;
    for (const Setting& s : settingTable()) {
        if (!s.sceneFile || !render.contains(s.name)) continue;
        const json& value = render[s.name];
        const std::string path = std::string("render.") + s.name;
        try {
            const bool named =
                value.is_string() && (s.kind == SettingKind::Choice ||
                                      (s.specialName && value.get<std::string>() == s.specialName));
            if (named)
                values.set(s, parseSetting(s, value.get<std::string>(), path));
            else if (s.kind != SettingKind::Choice && value.is_number())
                values.set(s, checkSetting(s, value.get<double>(), path));
            else
                refuseSetting(s, Fields::shown(value), path);
        } catch (const Error& e) {
            fields.fail(e.what());
        }
    }
    return values;
}

// "environment": {"color": [r, g, b]} or {"map": "sky.hdr", "intensity": 1, "rotation": 0}; the map is
// loaded by `loadMap` (relative to the scene file) after the whole file has been checked.
struct EnvironmentSpec {
    Environment environment;
    std::string mapPath;
};

EnvironmentSpec parseEnvironment(const json& environment, Fields& fields) {
    fields.object(environment, "environment");
    fields.checkKeys(environment, "environment.", {"color", "map", "intensity", "rotation"});
    EnvironmentSpec spec;
    bool hasColor = environment.contains("color"), hasMap = environment.contains("map");
    if (hasColor == hasMap)
        fields.fail(
            "environment needs either a \"color\" ([r, g, b] radiance) or a \"map\" (an .hdr or .exr file)");
    if (hasColor) {
        glm::vec3 color = fields.vec3(environment["color"], "environment.color");
        if (color.x < 0.0f || color.y < 0.0f || color.z < 0.0f)
            fields.fail("environment.color must not be negative");
        spec.environment.color = color;
    } else {
        spec.mapPath = fields.string(environment["map"], "environment.map");
        if (spec.mapPath.empty()) fields.fail("environment.map must not be empty");
    }
    if (environment.contains("intensity")) {
        float intensity = fields.real(environment["intensity"], "environment.intensity");
        if (intensity < 0.0f) fields.fail("environment.intensity must not be negative");
        spec.environment.intensity = intensity;
    }
    if (environment.contains("rotation"))
        spec.environment.rotationDegrees = fields.real(environment["rotation"], "environment.rotation");
    return spec;
}

// "lights": [{"type": "point", "position": [x, y, z], "intensity": I or [r, g, b], "color": [r, g, b]},
//            {"type": "spot", "position": ..., "direction": ..., "intensity": ..., "inner_cone": degrees,
//             "outer_cone": degrees},
//            {"type": "directional", "direction": [x, y, z], "irradiance": E or [r, g, b], "color": ...}]
// Units and meaning: PunctualLight (scene/scene.h). "direction" is the way the light travels (need not be
// of unit length); the strength is colour x intensity (or irradiance), the colour white if absent.
std::vector<PunctualLight> parseLights(const json& lights, Fields& fields) {
    fields.array(lights, "lights", "lights ({\"type\": \"point\", ...})");
    std::vector<PunctualLight> out;
    for (size_t i = 0; i < lights.size(); ++i) {
        const std::string path = "lights[" + std::to_string(i) + "]";
        const json& item = fields.object(lights[i], path);
        if (!item.contains("type")) fields.fail(path + " needs a \"type\": point, spot or directional");
        PunctualLight light;
        const std::string typeName = fields.string(item["type"], path + ".type");
        try {
            light.type = parseName(typeName, kAllPunctualLightTypes, punctualLightTypeName, "light type");
        } catch (const Error& e) {
            fields.fail(path + ".type: " + e.what());
        }
        const PunctualLightType type = light.type;
        const bool point = type == PunctualLightType::Point, spot = type == PunctualLightType::Spot,
                   directional = type == PunctualLightType::Directional;
        const std::string what = path + " (" + punctualLightTypeName(type) + ")";
        // Keys of another type of light are mistakes worth stopping for, not typos to warn about.
        if (directional && item.contains("position"))
            fields.fail(what +
                        ": a directional light has no \"position\" (it is infinitely far away; its "
                        "\"direction\" is the way its light travels)");
        if (point && item.contains("direction"))
            fields.fail(what +
                        ": a point light shines in every direction and takes no \"direction\" (a spot "
                        "light does)");
        if (!spot && (item.contains("inner_cone") || item.contains("outer_cone")))
            fields.fail(what + ": only spot lights have \"inner_cone\" and \"outer_cone\"");
        if (directional && item.contains("intensity"))
            fields.fail(what +
                        ": a directional light's strength is \"irradiance\" (W/m^2 on a surface facing "
                        "it), not \"intensity\" (W/sr, point and spot lights)");
        if (!directional && item.contains("irradiance"))
            fields.fail(what + ": a " + punctualLightTypeName(type) +
                        " light's strength is \"intensity\" (W/sr), not \"irradiance\" (W/m^2, directional "
                        "lights)");
        fields.checkKeys(item, path + ".",
                         {"type", "name", "color", "position", "direction", "intensity", "irradiance",
                          "inner_cone", "outer_cone"});
        if (item.contains("name")) light.name = fields.string(item["name"], path + ".name");

        const char* strengthKey = directional ? "irradiance" : "intensity";
        if (!item.contains(strengthKey))
            fields.fail(what + " needs \"" + strengthKey + "\" (" +
                        (directional ? "W/m^2 on a surface facing the light" : "W/sr") +
                        "): a number, or [r, g, b]");
        const std::string strengthPath = path + "." + strengthKey;
        const json& strength = item[strengthKey];
        glm::vec3 value = strength.is_number() ? glm::vec3(fields.real(strength, strengthPath))
                                               : fields.vec3(strength, strengthPath);
        glm::vec3 color(1.0f);
        if (item.contains("color")) color = fields.vec3(item["color"], path + ".color");
        if (glm::any(glm::lessThan(value, glm::vec3(0.0f))))
            fields.fail(strengthPath + " must not be negative");
        if (glm::any(glm::lessThan(color, glm::vec3(0.0f))))
            fields.fail(path + ".color must not be negative");
        light.intensity = color * value;

        if (!directional) {
            if (!item.contains("position")) fields.fail(what + " needs a \"position\": [x, y, z]");
            light.position = fields.vec3(item["position"], path + ".position");
        }
        if (!point) {
            if (!item.contains("direction"))
                fields.fail(what + " needs a \"direction\": [x, y, z], the way its light travels");
            glm::dvec3 d(fields.vec3(item["direction"], path + ".direction"));
            if (!(glm::length(d) > 0.0)) fields.fail(path + ".direction must not be the zero vector");
            light.direction = glm::vec3(glm::normalize(d));
        }
        if (spot) {
            float inner = 0.0f, outer = 45.0f;  // glTF's defaults, 0 and pi / 4
            if (item.contains("inner_cone")) inner = fields.real(item["inner_cone"], path + ".inner_cone");
            if (item.contains("outer_cone")) outer = fields.real(item["outer_cone"], path + ".outer_cone");
            if (!(outer > 0.0f && outer <= 90.0f))
                fields.fail(path +
                            ".outer_cone must be in (0, 90] degrees (from the axis to where the light "
                            "ends), got " +
                            std::to_string(outer));
            if (!(inner >= 0.0f && inner < outer))
                fields.fail(path + ".inner_cone must be at least 0 and less than outer_cone (" +
                            std::to_string(outer) + " degrees), got " + std::to_string(inner));
            light.innerConeAngle = glm::radians(inner);
            light.outerConeAngle = std::min(glm::radians(outer), 1.57079633f);
        }
        try {
            validatePunctualLight(light, path);
        } catch (const Error& e) {
            fields.fail(e.what());
        }
        out.push_back(light);
    }
    return out;
}

}  // namespace

Scene parseSceneFile(std::string_view bytes, const std::string& name, const MeshLoader& loadMesh,
                     const MapLoader& loadMap) {
    MapLoader noMaps = [&name](const std::string& map) -> Image {
        throw Error(name + ": environment map '" + map + "' cannot be loaded here");
    };
    std::string_view text = requireText(bytes, name);
    json root;
    try {
        root = json::parse(text.begin(), text.end(), nullptr, /*allow_exceptions=*/true,
                           /*ignore_comments=*/true);
    } catch (const json::parse_error& e) {
        throw Error(name + ": invalid JSON: " + withoutId(e) + " (byte " + std::to_string(e.byte) + ")");
    } catch (const json::exception& e) {
        // Numbers beyond double range (1e999) are refused while parsing, without a position.
        throw Error(name + ": invalid JSON: " + withoutId(e));
    }
    Fields fields(name);
    fields.object(root, "the top level");
    fields.checkKeys(root, "", {"mesh", "camera", "render", "environment", "lights"});
    if (!root.contains("mesh")) fields.fail("missing \"mesh\" (the .obj, .gltf or .glb file to render)");
    std::string mesh = fields.string(root["mesh"], "mesh");
    if (mesh.empty()) fields.fail("mesh must not be empty");
    std::optional<Camera> camera;
    if (root.contains("camera")) camera = parseCamera(root["camera"], fields);
    SettingValues settings;
    if (root.contains("render")) settings = parseRender(root["render"], fields);
    EnvironmentSpec environment;
    if (root.contains("environment")) environment = parseEnvironment(root["environment"], fields);
    std::vector<PunctualLight> lights;
    if (root.contains("lights")) lights = parseLights(root["lights"], fields);
    // Only after the whole file checked out: a typo in it should not cost a long mesh load first.
    Scene scene = loadMesh(mesh);
    fields.warnUnknownKeys();
    if (camera) scene.camera = camera;  // else the mesh's own (a glTF camera), if it has one
    scene.fileSettings = settings;
    scene.environment = environment.environment;
    // A glTF mesh may bring its own KHR_lights_punctual lights: the file's are added to them.
    scene.punctualLights.insert(scene.punctualLights.end(), lights.begin(), lights.end());
    if (!environment.mapPath.empty())
        scene.environment.map = (loadMap ? loadMap : noMaps)(environment.mapPath);
    scene.source = name;
    return scene;
}

namespace fs = std::filesystem;

Scene loadSceneFile(const std::string& path) {
    std::string bytes = readFileBytes(path);
    fs::path directory = fs::path(path).parent_path();
    return parseSceneFile(
        bytes, path,
        [&](const std::string& mesh) {
            fs::path meshPath = fs::path(mesh).is_absolute() ? fs::path(mesh) : directory / mesh;
            std::string ext = lowerCaseExtension(meshPath.string());
            if (ext != ".obj" && ext != ".gltf" && ext != ".glb")
                throw Error(path + ": mesh '" + mesh + "' must be an .obj, .gltf or .glb file");
            std::error_code ec;
            if (!fs::exists(meshPath, ec))
                throw Error(path + ": mesh '" + mesh + "' not found (looked for " + meshPath.string() + ")");
            return ext == ".obj" ? loadObj(meshPath.string()) : loadGltf(meshPath.string());
        },
        [&](const std::string& map) {
            fs::path mapPath = fs::path(map).is_absolute() ? fs::path(map) : directory / map;
            return loadEnvironmentMap(mapPath.string(), path + ": environment map '" + map + "'");
        });
}

Scene loadScene(const std::string& path) {
    if (path.empty()) throw Error("no scene file given (empty path)");
    std::error_code ec;
    if (!fs::exists(path, ec)) throw Error(path + ": no such file");
    std::string ext = lowerCaseExtension(path);
    if (ext == ".obj") return loadObj(path);
    if (ext == ".gltf" || ext == ".glb") return loadGltf(path);
    if (ext == ".json") return loadSceneFile(path);
    throw Error(path + ": unknown scene file type '" + ext + "' (expected .obj, .gltf, .glb or .json)");
}

}  // namespace fp
