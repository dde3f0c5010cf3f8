#include "image/pfm.h"

#include <cctype>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "core/error.h"
#include "core/file.h"
#include "image/file_io.h"
#include "image/image_check.h"

namespace fp {

namespace {

void appendLittleEndian(std::vector<std::uint8_t>& out, float value) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(bits >> (8 * i)));
}

float loadFloat(const std::uint8_t* p, bool littleEndian) {
    std::uint32_t bits = 0;
    for (int i = 0; i < 4; ++i) {
        const int shift = littleEndian ? 8 * i : 8 * (3 - i);
        bits |= std::uint32_t(p[i]) << shift;
    }
    float value = 0.0f;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

bool isSpace(std::uint8_t c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

// Walks the text header; every failure names the file.
class HeaderReader {
  public:
    HeaderReader(const std::vector<std::uint8_t>& bytes, const std::string& name)
        : bytes_(bytes), name_(name) {}

    [[noreturn]] void fail(const std::string& what) const {
        throw Error("'" + name_ + "' is not a valid PFM file: " + what);
    }

    // At least one whitespace byte must separate header fields.
    void skipSeparator(const char* before) {
        if (pos_ >= bytes_.size() || !isSpace(bytes_[pos_]))
            fail(std::string("expected whitespace after ") + before);
        while (pos_ < bytes_.size() && isSpace(bytes_[pos_])) ++pos_;
    }

    int readDimension(const char* what) {
        long long value = 0;
        size_t start = pos_;
        while (pos_ < bytes_.size() && std::isdigit(bytes_[pos_])) {
            value = value * 10 + (bytes_[pos_] - '0');
            if (value > INT_MAX) fail(std::string(what) + " is too large");
            ++pos_;
        }
        if (pos_ == start) fail(std::string("missing or malformed ") + what);
        if (value == 0) fail(std::string(what) + " is zero");
        return static_cast<int>(value);
    }

    float readScale() {
        std::string token;
        while (pos_ < bytes_.size() && !isSpace(bytes_[pos_]) && token.size() < 64) {
            token.push_back(static_cast<char>(bytes_[pos_++]));
        }
        char* end = nullptr;
        const float scale = std::strtof(token.c_str(), &end);
        if (token.empty() || end != token.c_str() + token.size()) fail("malformed scale '" + token + "'");
        if (!(std::isfinite(scale) && scale != 0.0f)) fail("scale must be finite and non-zero");
        return scale;
    }

    // The format puts exactly one whitespace byte between the scale and the binary data, which may
    // itself start with bytes that look like whitespace, so do not skip more than one.
    void skipFinalByte() {
        if (pos_ >= bytes_.size() || !isSpace(bytes_[pos_])) fail("expected a newline after the scale");
        ++pos_;
    }

    size_t position() const { return pos_; }
    void advance(size_t n) { pos_ += n; }

  private:
    const std::vector<std::uint8_t>& bytes_;
    const std::string& name_;
    size_t pos_ = 0;
};

}  // namespace

std::vector<std::uint8_t> encodePfm(const Image& image) {
    checkImageShape(image, "cannot encode PFM");
    const std::string header =
        "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
    std::vector<std::uint8_t> out(header.begin(), header.end());
    out.reserve(header.size() + image.pixels.size() * 12);
    for (int y = image.height - 1; y >= 0; --y) {
        for (int x = 0; x < image.width; ++x) {
            const glm::vec3& p = image.at(x, y);
            appendLittleEndian(out, p.r);
            appendLittleEndian(out, p.g);
            appendLittleEndian(out, p.b);
        }
    }
    return out;
}

Image decodePfm(const std::vector<std::uint8_t>& bytes, const std::string& name) {
    HeaderReader header(bytes, name);
    if (bytes.size() < 2 || bytes[0] != 'P' || (bytes[1] != 'F' && bytes[1] != 'f')) {
        header.fail("it does not start with \"PF\" or \"Pf\"");
    }
    const int channels = bytes[1] == 'F' ? 3 : 1;
    header.advance(2);
    header.skipSeparator("the magic number");
    const int width = header.readDimension("width");
    header.skipSeparator("the width");
    const int height = header.readDimension("height");
    header.skipSeparator("the height");
    const bool littleEndian = header.readScale() < 0.0f;
    header.skipFinalByte();

    // Compare sizes in 64 bits before allocating, so a corrupt header cannot request gigabytes.
    const unsigned long long expected = 4ull * static_cast<unsigned long long>(channels) *
                                        static_cast<unsigned long long>(width) *
                                        static_cast<unsigned long long>(height);
    const unsigned long long available = bytes.size() - header.position();
    if (available != expected) {
        throw Error("'" + name + "' is not a valid PFM file: a " + std::to_string(width) + "x" +
                    std::to_string(height) + " image needs " + std::to_string(expected) +
                    " bytes of pixel data but the file has " + std::to_string(available) +
                    (available < expected ? " (truncated)" : ""));
    }

    Image image(width, height);
    const std::uint8_t* p = bytes.data() + header.position();
    for (int row = 0; row < height; ++row) {
        const int y = height - 1 - row;  // stored bottom row first
        for (int x = 0; x < width; ++x) {
            glm::vec3& pixel = image.at(x, y);
            if (channels == 3) {
                pixel = {loadFloat(p, littleEndian), loadFloat(p + 4, littleEndian),
                         loadFloat(p + 8, littleEndian)};
            } else {
                pixel = glm::vec3(loadFloat(p, littleEndian));
            }
            p += 4 * channels;
        }
    }
    return image;
}

void writePfm(const std::string& path, const Image& image) {
    checkImageShape(image, "cannot write '" + path + "'");
    writeFileAtomically(path, encodePfm(image));
}

Image readPfm(const std::string& path) {
    const std::string bytes = readFileBytes(path);
    return decodePfm(std::vector<std::uint8_t>(bytes.begin(), bytes.end()), path);
}

}  // namespace fp
