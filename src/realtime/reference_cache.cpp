#include "realtime/reference_cache.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "image/file_io.h"
#include "settings/setting_table.h"

namespace fp {

namespace {

std::optional<std::string> readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

void writeText(const std::string& path, const std::string& text) {
    writeFileAtomically(path, std::vector<std::uint8_t>(text.begin(), text.end()));
}

std::string vec(const glm::vec3& v) {
    char text[160];
    std::snprintf(text, sizeof text, "%.9g %.9g %.9g", v.x, v.y, v.z);  // 9 digits: floats exactly
    return text;
}

}  // namespace

ReferenceCache::ReferenceCache(std::string dir, const std::string& key) : dir_(std::move(dir)) {
    std::error_code error;
    std::filesystem::create_directories(dir_, error);
    if (error || !std::filesystem::is_directory(dir_))
        throw Error("--reference-cache " + dir_ + " cannot be created" +
                    (error ? ": " + error.message() : ""));
    const std::string keyPath = dir_ + "/key.txt";
    if (std::optional<std::string> stored = readText(keyPath)) {
        if (*stored != key)
            throw Error("--reference-cache " + dir_ + " holds references of other settings (" + keyPath +
                        "):\n" + *stored + "this run's are:\n" + key +
                        "use another directory or empty this one");
    } else {
        writeText(keyPath, key);
    }
}

std::string ReferenceCache::framePath(int frame, const char* extension) const {
    char name[48];
    std::snprintf(name, sizeof name, "/reference_%04d.%s", frame, extension);
    return dir_ + name;
}

std::optional<Image> ReferenceCache::find(int frame, const Camera& camera) const {
    const std::string imagePath = framePath(frame, "exr");
    std::optional<std::string> storedCamera = readText(framePath(frame, "camera"));
    if (!storedCamera || !std::filesystem::exists(imagePath)) return std::nullopt;
    if (*storedCamera != describe(camera))
        throw Error("--reference-cache: " + imagePath + " was rendered from another camera (" +
                    *storedCamera + ") than this run's frame " + std::to_string(frame) + " (" +
                    describe(camera) +
                    "): another camera path, --fps or --orbit-speed; use another directory");
    return readImage(imagePath);
}

void ReferenceCache::store(int frame, const Camera& camera, const Image& reference) const {
    writeImage(framePath(frame, "exr"), reference);  // first the image, then the camera that vouches for it
    writeText(framePath(frame, "camera"), describe(camera));
}

// The scene and every setting the image depends on (the settings table's rows that enter a partial
// render's fingerprint), a line each.
std::string ReferenceCache::describe(const std::string& scene, const RenderSettings& s, int referenceSpp) {
    std::string text = "scene " + scene + "\n";
    for (const Setting& setting : settingTable())
        if (setting.effects & (kEntersFingerprint | kEntersFingerprintIfChosen))
            text += std::string(setting.name) + " " + settingText(setting, setting.get(s)) + "\n";
    return text + "reference spp " + std::to_string(referenceSpp) + "\n";
}

std::string ReferenceCache::describe(const Camera& c) {
    char text[160];
    std::snprintf(text, sizeof text, " fov %.9g aperture %.9g focus %.9g\n", c.fovY, c.aperture,
                  c.focusDistance ? *c.focusDistance : -1.0f);
    return "eye " + vec(c.eye) + " target " + vec(c.target) + " up " + vec(c.up) + text;
}

}  // namespace fp
