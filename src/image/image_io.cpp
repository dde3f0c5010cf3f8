// writeImage / readImage from image.h: pick the format by the file name's extension.
#include "core/error.h"
#include "core/text.h"
#include "image/exr.h"
#include "image/hdr.h"
#include "image/image.h"
#include "image/pfm.h"
#include "image/png.h"

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

}  // namespace fp
