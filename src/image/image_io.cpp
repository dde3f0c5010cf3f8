// writeImage / readImage from image.h: pick the format by the file name's extension.
#include "core/error.h"
#include "core/file.h"
#include "core/text.h"
#include "image/exr.h"
#include "image/hdr.h"
#include "image/image.h"
#include "image/pfm.h"
#include "image/png.h"
#include "image/rgba8_image.h"
#include "image/tone_map.h"

namespace fp {

void writeImage(const std::string& path, const Image& image, const DisplaySettings& display) {
    const std::string extension = lowerCaseExtension(path);
    if (extension == ".pfm") return writePfm(path, image);
    if (extension == ".exr") return writeExr(path, image);
    if (extension == ".png") return writePng(path, image, display);
    throw Error("cannot write '" + path + "': unknown image extension '" + extension +
                "' (use .png, .exr or .pfm)");
}

Image readImage(const std::string& path) {
    const std::string extension = lowerCaseExtension(path);
    if (extension == ".pfm") return readPfm(path);
    if (extension == ".exr") return readExr(path);
    if (extension == ".hdr") return readHdr(path);
    throw Error("cannot read '" + path + "': unsupported image extension '" + extension +
                "' (only linear .exr, .pfm and .hdr images can be read)");
}

Image readImageOrPng(const std::string& path) {
    if (lowerCaseExtension(path) != ".png") return readImage(path);
    const Rgba8Image codes = decodeRgba8(readFileBytes(path), "'" + path + "'");
    Image image(codes.width, codes.height);
    for (size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) image.pixels[i][c] = srgbDecode(codes.texels[4 * i + size_t(c)] / 255.0f);
    return image;
}

}  // namespace fp
