#include "render/aovs.h"

#include <algorithm>

#include "core/error.h"
#include "core/text.h"

namespace fp {

const std::vector<Aov>& allAovs() {
    static const std::vector<Aov> aovs = {Aov::Albedo, Aov::Normal, Aov::Depth};
    return aovs;
}

const char* aovName(Aov aov) {
    static constexpr const char* kNames[] = {"albedo", "normal", "depth"};  // in enum order
    return nameOf(aov, kNames);
}

std::vector<std::string> aovChannels(Aov aov) {
    switch (aov) {
        case Aov::Albedo:
            return {"R", "G", "B"};
        case Aov::Normal:
            return {"X", "Y", "Z"};
        case Aov::Depth:
            return {"Z"};
    }
    return {};
}

std::vector<Aov> parseAovs(const std::string& list) {
    std::vector<Aov> aovs;
    for (const std::string& name : splitNameList(list, "--aovs")) {
        auto it = std::find_if(allAovs().begin(), allAovs().end(), [&](Aov a) { return name == aovName(a); });
        if (it == allAovs().end()) {
            std::string choices;
            for (Aov a : allAovs()) choices += std::string(choices.empty() ? "" : ", ") + aovName(a);
            throw Error("--aovs: unknown AOV '" + name + "' (choose from " + choices +
                        ", separated by commas)");
        }
        aovs.push_back(*it);
    }
    return aovs;
}

std::vector<Aov> parseAovOption(const std::optional<std::string>& list, const std::string& output) {
    if (!list) return {};
    std::vector<Aov> aovs = parseAovs(*list);
    if (lowerCaseExtension(output) != ".exr")
        throw Error("--aovs needs an .exr output (its layers hold them), not " + output);
    return aovs;
}

std::vector<AovImage> aovImages(const Accumulation& acc, const std::vector<Aov>& aovs) {
    std::vector<AovImage> images;
    const size_t pixels = size_t(acc.width) * size_t(acc.height);
    for (Aov aov : aovs) {
        AovImage out{aov, Image(acc.width, acc.height)};
        for (size_t i = 0; i < pixels; ++i) {
            const float guideSamples = acc.albedo[i].a, hits = acc.counters[i].z;
            glm::vec3& v = out.image.pixels[i];
            if (aov == Aov::Albedo && guideSamples > 0.0f) v = glm::vec3(acc.albedo[i]) / guideSamples;
            if (aov == Aov::Normal && guideSamples > 0.0f) v = glm::vec3(acc.normalDepth[i]) / guideSamples;
            if (aov == Aov::Depth && hits > 0.0f) v = glm::vec3(acc.normalDepth[i].w / hits, 0.0f, 0.0f);
        }
        images.push_back(std::move(out));
    }
    return images;
}

std::optional<AovImage> combineAov(Aov aov, const std::vector<AovPart>& parts) {
    struct Held {
        const Image* image;
        const std::vector<double>* samples;
    };
    std::vector<Held> held;
    for (const AovPart& part : parts)
        for (const AovImage& image : *part.aovs)
            if (image.aov == aov) held.push_back({&image.image, &part.samples});
    if (held.empty()) return std::nullopt;
    const Image& first = *held[0].image;
    AovImage out{aov, Image(first.width, first.height)};
    double samplesSeen = 0.0;
    for (size_t i = 0; i < out.image.pixels.size(); ++i) {
        glm::dvec3 sum(0.0);
        double weight = 0.0;
        for (const Held& h : held) {
            if (h.image->pixels.size() != out.image.pixels.size())
                throw Error(std::string("the ") + aovName(aov) + " layers of the parts differ in size");
            const std::vector<double>& samples = *h.samples;
            double n = samples.empty() ? 0.0 : samples.size() == 1 ? samples[0] : samples.at(i);
            const glm::vec3& v = h.image->pixels[i];
            samplesSeen += n;
            if (aov == Aov::Depth && v.x == 0.0f) continue;  // no hit there: no distance to average
            sum += glm::dvec3(v) * n;
            weight += n;
        }
        if (weight > 0.0) out.image.pixels[i] = glm::vec3(sum / weight);
    }
    if (samplesSeen == 0.0) return std::nullopt;
    return out;
}

ExrLayer toExrLayer(const AovImage& aov) {
    return {aovName(aov.aov), aovChannels(aov.aov), aov.image};
}

std::vector<AovImage> aovsFromExrLayers(const std::vector<ExrLayer>& layers) {
    std::vector<AovImage> aovs;
    for (Aov aov : allAovs())
        for (const ExrLayer& layer : layers)
            if (layer.name == aovName(aov) && layer.channels == aovChannels(aov))
                aovs.push_back({aov, layer.image});
    return aovs;
}

}  // namespace fp
