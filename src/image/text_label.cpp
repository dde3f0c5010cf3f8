#include "image/text_label.h"

#include <algorithm>
#include <vector>

#include <stb_easy_font.h>

#include "core/error.h"

namespace fp {

namespace {

// stb_easy_font indexes its tables by character - 32 without checking, and takes a mutable string.
std::vector<char> checked(const std::string& text, int scale) {
    if (scale < 1) throw Error("text label: scale " + std::to_string(scale) + " is below 1");
    for (char c : text)
        if (c < ' ' || c > '~')
            throw Error("text label: character " + std::to_string(int(static_cast<unsigned char>(c))) +
                        " in \"" + text + "\" is not printable ASCII");
    std::vector<char> copy(text.begin(), text.end());
    copy.push_back('\0');
    return copy;
}

}  // namespace

TextExtent textExtent(const std::string& text, int scale) {
    std::vector<char> copy = checked(text, scale);
    if (text.empty()) return {0, 0};
    return {stb_easy_font_width(copy.data()) * scale, kTextRows * scale};
}

void drawText(Image& image, const std::string& text, int left, int top, int scale, glm::vec3 colour) {
    drawText(image, text, left, top, scale, colour, PixelRect{0, 0, image.width, image.height});
}

void drawText(Image& image, const std::string& text, int left, int top, int scale, glm::vec3 colour,
              const PixelRect& clip) {
    const int clipLeft = std::max(clip.x, 0), clipTop = std::max(clip.y, 0);
    const int clipRight = std::min(clip.x + clip.width, image.width);
    const int clipBottom = std::min(clip.y + clip.height, image.height);
    std::vector<char> copy = checked(text, scale);
    // Vertices of 16 bytes (x, y, z as floats, an RGBA8 colour), four per quad; stb_easy_font's header
    // expects about 270 bytes a character, so 64 quads a character is ample.
    struct Vertex {
        float x, y, z;
        unsigned char rgba[4];
    };
    static_assert(sizeof(Vertex) == 16, "stb_easy_font's vertex layout");
    std::vector<Vertex> vertices(text.size() * 64 * 4 + 4);
    int quads = stb_easy_font_print(0.0f, 0.0f, copy.data(), nullptr, vertices.data(),
                                    int(vertices.size() * sizeof(Vertex)));
    for (int q = 0; q < quads; ++q) {
        // Vertex 0 is the top-left corner, vertex 2 the bottom-right; all on whole font pixels.
        const Vertex &a = vertices[size_t(q) * 4], &b = vertices[size_t(q) * 4 + 2];
        int x0 = left + int(a.x) * scale, x1 = left + int(b.x) * scale;
        int y0 = top + int(a.y) * scale, y1 = top + int(b.y) * scale;
        for (int y = std::max(y0, clipTop); y < std::min(y1, clipBottom); ++y)
            for (int x = std::max(x0, clipLeft); x < std::min(x1, clipRight); ++x) image.at(x, y) = colour;
    }
}

}  // namespace fp
