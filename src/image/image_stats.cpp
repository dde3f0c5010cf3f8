#include "image/image_stats.h"

#include <cmath>
#include <string>

#include "core/error.h"

namespace fp {

namespace {

std::string sizeText(const Image& image) {
    return std::to_string(image.width) + "x" + std::to_string(image.height);
}

}  // namespace

glm::dvec3 meanColor(const Image& image) {
    if (image.width <= 0 || image.height <= 0) throw Error("mean of an empty image");
    return meanColor(image, PixelRect{0, 0, image.width, image.height});
}

glm::dvec3 meanColor(const Image& image, const PixelRect& rect) {
    if (rect.width <= 0 || rect.height <= 0 || rect.x < 0 || rect.y < 0 ||
        rect.x > image.width - rect.width || rect.y > image.height - rect.height) {
        throw Error("rectangle " + std::to_string(rect.width) + "x" + std::to_string(rect.height) + " at (" +
                    std::to_string(rect.x) + ", " + std::to_string(rect.y) + ") is empty or outside the " +
                    sizeText(image) + " image");
    }
    glm::dvec3 sum(0.0);
    for (int y = rect.y; y < rect.y + rect.height; ++y) {
        for (int x = rect.x; x < rect.x + rect.width; ++x) sum += glm::dvec3(image.at(x, y));
    }
    return sum / (double(rect.width) * double(rect.height));
}

double rmse(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height) {
        throw Error("cannot compare a " + sizeText(a) + " image with a " + sizeText(b) + " image");
    }
    if (a.pixels.empty() || a.pixels.size() != b.pixels.size()) throw Error("cannot compare empty images");
    double sum = 0.0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        const glm::dvec3 d = glm::dvec3(a.pixels[i]) - glm::dvec3(b.pixels[i]);
        sum += glm::dot(d, d);
    }
    return std::sqrt(sum / (3.0 * double(a.pixels.size())));
}

bool allFinite(const Image& image) {
    for (const glm::vec3& p : image.pixels) {
        if (!std::isfinite(p.r) || !std::isfinite(p.g) || !std::isfinite(p.b)) return false;
    }
    return true;
}

}  // namespace fp
