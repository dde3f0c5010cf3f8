#pragma once
// A test image whose pixels all differ: red is the image's tag, green and blue its column and row, so
// that a pixel pasted into a figure (image_grid.h, the study's strip) shows where it came from.
#include "image/image.h"

namespace fp::test {

inline Image taggedImage(int width, int height, float tag) {
    Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) image.at(x, y) = glm::vec3(tag, 0.01f * float(x), 0.01f * float(y));
    return image;
}

}  // namespace fp::test
