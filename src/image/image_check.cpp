#include "image/image_check.h"

#include "core/error.h"

namespace fp {

void checkImageShape(const Image& image, const std::string& context) {
    const std::string size = std::to_string(image.width) + "x" + std::to_string(image.height);
    if (image.width <= 0 || image.height <= 0) throw Error(context + ": the image is empty (" + size + ")");
    if (image.pixels.size() != size_t(image.width) * size_t(image.height)) {
        throw Error(context + ": a " + size + " image has " + std::to_string(image.pixels.size()) +
                    " pixels");
    }
}

}  // namespace fp
