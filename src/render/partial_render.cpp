#include "render/partial_render.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "core/error.h"
#include "core/text.h"
#include "image/image.h"
#include "render/view_image.h"
#include "settings/setting_table.h"

namespace fp {

uint64_t PartialRender::samples() const {
    uint64_t total = 0;
    for (const SampleRange& r : ranges) total += r.count;
    return total;
}

namespace {

// FNV-1a, 64 bits (Fowler, Noll, Vo): a fingerprint, not a defence against forgery.
struct Fnv {
    uint64_t h = 1469598103934665603ull;
    void bytes(const void* data, size_t size) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < size; ++i) h = (h ^ p[i]) * 1099511628211ull;
    }
    template <typename T>
    void value(const T& v) {
        bytes(&v, sizeof v);
    }
};

const char* kRanges = "fragpath.sample_ranges";  // "first+count,first+count,..."
const char* kFingerprint = "fragpath.fingerprint";
const char* kSamples = "fragpath.samples";

std::string formatRanges(const std::vector<SampleRange>& ranges) {
    std::string text;
    for (const SampleRange& r : ranges)
        text += (text.empty() ? "" : ",") + std::to_string(r.first) + "+" + std::to_string(r.count);
    return text;
}

std::vector<SampleRange> parseRanges(const std::string& text, const std::string& name) {
    std::vector<SampleRange> ranges;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');) {
        unsigned long long first = 0, count = 0;
        char plus = 0;
        std::istringstream one(item);
        if (!(one >> first >> plus >> count) || plus != '+' || count == 0)
            throw Error(name + ": malformed sample range '" + item + "' in the EXR header");
        ranges.push_back({first, count});
    }
    if (ranges.empty()) throw Error(name + ": no sample ranges in the EXR header");
    return ranges;
}

}  // namespace

std::string renderFingerprint(const Scene& scene, const RenderSettings& settings, const Camera& camera) {
    Fnv f;
    auto triangles = [&f](const std::vector<Triangle>& list) {
        for (const Triangle& t : list) {
            f.value(t.p);
            f.value(t.n);
            f.value(t.material);
        }
    };
    triangles(scene.triangles);
    // Instances (none in most scenes: their fingerprint is the one they had before instancing).
    for (const InstancedMesh& mesh : scene.meshes) triangles(mesh.triangles);
    for (const Instance& instance : scene.instances) {
        f.value(instance.mesh);
        f.value(instance.objectToWorld);
    }
    for (const Material& m : scene.materials) {
        f.value(m.type);
        f.value(m.diffuse);
        f.value(m.emission);
        f.value(m.specular);
        f.value(m.transmission);
        f.value(m.roughness);
        f.value(m.ior);
        f.value(m.abbeNumber);
        // The fields of the metallic-roughness model, alpha and maps, only where they differ from the
        // defaults: a scene without them keeps the fingerprint it had before they existed.
        const Material defaults;
        if (m.metallic != defaults.metallic || m.alpha != defaults.alpha ||
            m.alphaMode != defaults.alphaMode || m.alphaCutoff != defaults.alphaCutoff ||
            m.doubleSided != defaults.doubleSided || m.normalScale != defaults.normalScale ||
            m.textureIndices() != defaults.textureIndices()) {
            f.value(m.metallic);
            f.value(m.alpha);
            f.value(m.alphaMode);
            f.value(m.alphaCutoff);
            f.value(m.doubleSided);
            f.value(m.normalScale);
            f.value(m.textureIndices());
        }
    }
    const Environment& e = scene.environment;
    f.value(e.color);
    f.value(e.intensity);
    f.value(e.rotationDegrees);
    f.bytes(e.map.pixels.data(), e.map.pixels.size() * sizeof(glm::vec3));
    // Only scenes that have them, so that every other scene keeps the fingerprint it had.
    for (const PunctualLight& l : scene.punctualLights) {
        f.value(l.type);
        f.value(l.position);
        f.value(l.direction);
        f.value(l.intensity);
        f.value(l.innerConeAngle);
        f.value(l.outerConeAngle);
    }
    f.value(camera.eye);
    f.value(camera.target);
    f.value(camera.up);
    f.value(camera.fovY);
    // The lens only when there is one, so that a pinhole's fingerprint is what it was before lenses
    // existed (its saved renders still resume and merge); then the focus distance it renders with.
    if (camera.aperture > 0.0f) {
        f.value(camera.aperture);
        f.value(resolvedFocusDistance(camera));
    }
    // The settings table's rows in order, each value as the type it had when fingerprints began (a
    // float for a number, 32 bits for the rest), so that saved renders still resume and merge.
    for (const Setting& setting : settingTable()) {
        const double value = setting.get(settings);
        const bool chosen = value != settingDefault(setting);
        if (!(setting.effects & kEntersFingerprint) &&
            !((setting.effects & kEntersFingerprintIfChosen) && chosen))
            continue;
        if (setting.kind == SettingKind::Number)
            f.value(float(value));
        else
            f.value(uint32_t(int64_t(value)));
    }
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", (unsigned long long)f.h);
    return text;
}

void writePartial(const std::string& path, const PartialRender& partial) {
    std::vector<ExrLayer> layers;
    for (const AovImage& aov : partial.aovs) layers.push_back(toExrLayer(aov));
    writeExr(path, partial.mean,
             {{kRanges, formatRanges(partial.ranges)},
              {kSamples, std::to_string(partial.samples())},
              {kFingerprint, partial.fingerprint}},
             layers);
}

void writeRenderOutput(const std::string& path, const PartialRender& partial, const DisplaySettings& display,
                       View view) {
    if (lowerCaseExtension(path) == ".exr")
        writePartial(path, partial);
    else
        writeRenderedView(path, partial.mean, view, display);
}

PartialRender readPartial(const std::string& path) {
    ExrAttributes attributes;
    std::vector<ExrLayer> layers;
    PartialRender partial;
    partial.mean = readExr(path, &attributes, &layers);
    partial.aovs = aovsFromExrLayers(layers);
    std::string ranges;
    for (const auto& [key, value] : attributes) {
        if (key == kRanges) ranges = value;
        if (key == kFingerprint) partial.fingerprint = value;
    }
    if (ranges.empty() || partial.fingerprint.empty())
        throw Error(path + ": not a partial render from fragpath (its EXR header has no sample ranges)");
    partial.ranges = parseRanges(ranges, path);
    return partial;
}

PartialRender mergePartials(const std::vector<PartialRender>& parts, const std::vector<std::string>& names) {
    if (parts.empty()) throw Error("merge needs at least one partial render");
    PartialRender out;
    out.fingerprint = parts[0].fingerprint;
    out.mean = Image(parts[0].mean.width, parts[0].mean.height);
    std::vector<glm::dvec3> sums(out.mean.pixels.size(), glm::dvec3(0.0));
    for (size_t i = 0; i < parts.size(); ++i) {
        const PartialRender& p = parts[i];
        if (p.fingerprint != out.fingerprint)
            throw Error(names[i] + " was rendered from a different scene or settings than " + names[0] +
                        " (fingerprint " + p.fingerprint + " vs " + out.fingerprint + ")");
        if (p.mean.width != out.mean.width || p.mean.height != out.mean.height)
            throw Error(names[i] + " has a different size than " + names[0]);
        double n = double(p.samples());
        for (size_t k = 0; k < sums.size(); ++k) sums[k] += glm::dvec3(p.mean.pixels[k]) * n;
        out.ranges.insert(out.ranges.end(), p.ranges.begin(), p.ranges.end());
    }
    std::sort(out.ranges.begin(), out.ranges.end(),
              [](const SampleRange& a, const SampleRange& b) { return a.first < b.first; });
    for (size_t i = 1; i < out.ranges.size(); ++i)
        if (out.ranges[i].first < out.ranges[i - 1].end())
            throw Error("sample ranges overlap: samples " + std::to_string(out.ranges[i].first) + ".." +
                        std::to_string(out.ranges[i - 1].end() - 1) + " are in two of the inputs");
    // Adjacent ranges become one.
    std::vector<SampleRange> joined;
    for (const SampleRange& r : out.ranges)
        if (!joined.empty() && joined.back().end() == r.first)
            joined.back().count += r.count;
        else
            joined.push_back(r);
    out.ranges = joined;
    double total = double(out.samples());
    for (size_t k = 0; k < sums.size(); ++k) out.mean.pixels[k] = glm::vec3(sums[k] / total);
    std::vector<AovPart> aovParts;
    for (const PartialRender& p : parts) aovParts.push_back({&p.aovs, {double(p.samples())}});
    for (const AovImage& aov : parts[0].aovs) {
        bool everyPart = std::all_of(parts.begin(), parts.end(), [&](const PartialRender& p) {
            return std::any_of(p.aovs.begin(), p.aovs.end(),
                               [&](const AovImage& a) { return a.aov == aov.aov; });
        });
        if (!everyPart) continue;
        if (std::optional<AovImage> merged = combineAov(aov.aov, aovParts))
            out.aovs.push_back(std::move(*merged));
    }
    return out;
}

std::vector<AovImage> outputAovs(const Accumulation& acc, const std::vector<Aov>& aovs,
                                 const std::optional<PartialRender>& resumed) {
    const std::vector<AovImage> now = aovImages(acc, aovs);
    AovPart rendered{&now, std::vector<double>(acc.albedo.size())};
    for (size_t i = 0; i < acc.albedo.size(); ++i) rendered.samples[i] = acc.albedo[i].a;  // guide samples
    std::vector<AovPart> parts = {rendered};
    if (resumed) parts.push_back({&resumed->aovs, {double(resumed->samples())}});
    std::vector<AovImage> out;
    for (Aov aov : aovs) {
        std::optional<AovImage> combined = combineAov(aov, parts);
        if (!combined)
            throw Error(std::string("no samples for the ") + aovName(aov) +
                        " AOV: the resumed render has no such layer and no samples were rendered now");
        out.push_back(std::move(*combined));
    }
    return out;
}

}  // namespace fp
