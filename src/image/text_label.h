#pragma once
// Text drawn into an Image, for labels on figures written as PNG (the study's and the real-time run's
// image strips). The glyphs are Sean Barrett's stb_easy_font (public domain, Debian's libstb-dev): each
// character is a few axis-aligned quads on a pixel grid, 7 rows above the baseline and 2 below, which
// are filled here at an integer scale, so the text is exact pixels without anti-aliasing.
#include <string>

#include <glm/glm.hpp>

#include "image/image.h"
#include "image/image_stats.h"

namespace fp {

// Rows of the glyphs at scale 1: capitals and digits fill rows 0-6, descenders (g, j, p, q, y) reach 8.
constexpr int kTextRows = 9;

struct TextExtent {
    int width = 0, height = 0;
};

// The pixels `text` (one line of printable ASCII) covers at `scale`: stb_easy_font's advance widths
// (which end in a column or two of spacing) by kTextRows, both times `scale`. Throws fp::Error
// for a character outside ' '..'~' (a newline included) or a scale below 1.
TextExtent textExtent(const std::string& text, int scale);

// Fills the glyphs of `text` with `colour`, its top-left corner at (left, top), each font pixel a
// scale x scale square; pixels outside the image, or outside `clip`, are left as they are. Throws as
// textExtent does.
void drawText(Image& image, const std::string& text, int left, int top, int scale, glm::vec3 colour);
void drawText(Image& image, const std::string& text, int left, int top, int scale, glm::vec3 colour,
              const PixelRect& clip);

}  // namespace fp
