#pragma once
// Images side by side in rows and columns, 2-pixel mid-grey gaps between them, with a header row naming
// the columns and a label column naming the rows: a figure that explains itself (the study's strip of
// sample counts, the real-time run's frames above their references).
//
// Layout (s: the text scale, 2 for tiles of at least 96 pixels a side, else 1; padding p = 2 s):
//   header row     9 s + 2 p = 13 s rows when there are column labels, else none
//   label column   the widest row label (text_label.h's textExtent) + 2 p when there are row labels
//   tiles          tile (c, r) at (label column + c (width + 2), header + r (height + 2))
// A column label is centred over its tile, or starts at the tile's left edge and is cut at its right
// edge if it is wider; a row label is centred on its row's height.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "image/image.h"
#include "image/image_stats.h"

namespace fp {

constexpr int kGridGap = 2;
const glm::vec3 kGridGapColour(0.18f);  // mid grey after the sRGB encoding

struct GridLabels {
    std::vector<std::string> columns;  // one per column, or none: no header row
    std::vector<std::string> rows;     // one per row, or none: no label column
    // Radiance of the text: 1 is white after a clamp tone map at exposure 0.
    glm::vec3 colour{1.0f};
};

struct GridLayout {
    int tileWidth = 0, tileHeight = 0;
    int scale = 1, padding = 2;
    int labelWidth = 0, headerHeight = 0;  // 0: no label column, no header row
    int width = 0, height = 0;             // of the whole image
    int tileLeft(int column) const { return labelWidth + column * (tileWidth + kGridGap); }
    int tileTop(int row) const { return headerHeight + row * (tileHeight + kGridGap); }
};

// Throws fp::Error if there are no rows or columns, or a label list has neither 0 entries nor one per
// row or column, or a label is not printable ASCII.
GridLayout gridLayout(int rows, int columns, int tileWidth, int tileHeight, const GridLabels& labels);

// tiles[r][c] is the image in row r, column c; each shows its `crop`. Throws fp::Error (as gridLayout,
// and) if the rows differ in length or a crop is not inside its image.
Image assembleGrid(const std::vector<std::vector<const Image*>>& tiles, const PixelRect& crop,
                   const GridLabels& labels);

}  // namespace fp
