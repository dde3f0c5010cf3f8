#include "image/error_metrics.h"

#include <cmath>
#include <string>

#include "core/error.h"
#include "image/tone_map.h"

namespace fp {

namespace {

void checkComparable(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height)
        throw Error("cannot compare a " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                    " image with a " + std::to_string(b.width) + "x" + std::to_string(b.height) + " image");
    if (a.pixels.empty()) throw Error("cannot compare empty images");
}

// The normalised 1D Gaussian of the SSIM window; the 2D window is its outer product.
std::vector<double> gaussianWeights() {
    const double sigma = 1.5;
    std::vector<double> w(kSsimWindow);
    double sum = 0.0;
    for (int i = 0; i < kSsimWindow; ++i) {
        double x = i - kSsimWindow / 2;
        w[size_t(i)] = std::exp(-0.5 * x * x / (sigma * sigma));
        sum += w[size_t(i)];
    }
    for (double& v : w) v /= sum;
    return w;
}

}  // namespace

double relativeMse(const Image& estimate, const Image& reference, double epsilon) {
    checkComparable(estimate, reference);
    double sum = 0.0;
    for (size_t i = 0; i < estimate.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            double x = estimate.pixels[i][c], y = reference.pixels[i][c];
            sum += (x - y) * (x - y) / (y * y + epsilon);
        }
    return sum / (3.0 * double(estimate.pixels.size()));
}

double expectedRelativeMse(const Image& variance, const Image& reference, double epsilon) {
    checkComparable(variance, reference);
    double sum = 0.0;
    for (size_t i = 0; i < variance.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            double y = reference.pixels[i][c];
            sum += variance.pixels[i][c] / (y * y + epsilon);
        }
    return sum / (3.0 * double(variance.pixels.size()));
}

std::vector<float> displayLuma(const Image& image) {
    std::vector<float> luma(image.pixels.size());
    for (size_t i = 0; i < luma.size(); ++i) {
        glm::vec3 e = displayEncode(image.pixels[i], DisplaySettings{});
        luma[i] = 0.2126f * e.r + 0.7152f * e.g + 0.0722f * e.b;
    }
    return luma;
}

double ssim(const Image& estimate, const Image& reference) {
    checkComparable(estimate, reference);
    if (estimate.width < kSsimWindow || estimate.height < kSsimWindow)
        throw Error("SSIM needs an image of at least " + std::to_string(kSsimWindow) + "x" +
                    std::to_string(kSsimWindow) + " pixels");
    const double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;  // (K1 L)^2, (K2 L)^2 with L = 1
    const std::vector<float> x = displayLuma(estimate), y = displayLuma(reference);
    const std::vector<double> w = gaussianWeights();
    const int width = estimate.width;
    double total = 0.0;
    int windows = 0;
    for (int y0 = 0; y0 + kSsimWindow <= estimate.height; ++y0)
        for (int x0 = 0; x0 + kSsimWindow <= width; ++x0) {
            double mx = 0, my = 0, sxx = 0, syy = 0, sxy = 0;
            for (int j = 0; j < kSsimWindow; ++j)
                for (int i = 0; i < kSsimWindow; ++i) {
                    size_t p = size_t(y0 + j) * size_t(width) + size_t(x0 + i);
                    double wt = w[size_t(i)] * w[size_t(j)], a = x[p], b = y[p];
                    mx += wt * a, my += wt * b;
                    sxx += wt * a * a, syy += wt * b * b, sxy += wt * a * b;
                }
            double vx = sxx - mx * mx, vy = syy - my * my, cov = sxy - mx * my;
            total += (2 * mx * my + c1) * (2 * cov + c2) / ((mx * mx + my * my + c1) * (vx + vy + c2));
            ++windows;
        }
    return total / windows;
}

}  // namespace fp
