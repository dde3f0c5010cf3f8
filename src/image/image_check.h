#pragma once
// Shape validation shared by the writers: an Image is a plain struct, so nothing stops a caller from
// building one whose pixel count disagrees with its size, and the file formats cannot hold 0x0 images.
#include <string>

#include "image/image.h"

namespace fp {

// Throws fp::Error starting with `context` (e.g. "cannot write 'out.png'") if `image` has a
// non-positive size or width*height != pixels.size().
void checkImageShape(const Image& image, const std::string& context);

}  // namespace fp
