#include "image/image_grid.h"

#include <algorithm>

#include "core/error.h"
#include "image/text_label.h"

namespace fp {

namespace {

void checkCount(size_t labels, int expected, const char* what) {
    if (labels != 0 && labels != size_t(expected))
        throw Error("image grid: " + std::to_string(labels) + " " + what + " labels for " +
                    std::to_string(expected) + " " + what + "s");
}

}  // namespace

GridLayout gridLayout(int rows, int columns, int tileWidth, int tileHeight, const GridLabels& labels) {
    if (rows < 1 || columns < 1 || tileWidth < 1 || tileHeight < 1)
        throw Error("image grid: " + std::to_string(rows) + " rows of " + std::to_string(columns) +
                    " tiles of " + std::to_string(tileWidth) + "x" + std::to_string(tileHeight));
    checkCount(labels.rows.size(), rows, "row");
    checkCount(labels.columns.size(), columns, "column");
    GridLayout l;
    l.tileWidth = tileWidth;
    l.tileHeight = tileHeight;
    // Text 9 rows high at scale 1 is legible on small tiles; at 2 it reads at the size of a 128-pixel
    // tile without taking much of it.
    l.scale = std::min(tileWidth, tileHeight) >= 96 ? 2 : 1;
    l.padding = 2 * l.scale;
    if (!labels.columns.empty()) {
        for (const std::string& label : labels.columns) textExtent(label, l.scale);  // validates
        l.headerHeight = kTextRows * l.scale + 2 * l.padding;
    }
    if (!labels.rows.empty()) {
        int widest = 0;
        for (const std::string& label : labels.rows)
            widest = std::max(widest, textExtent(label, l.scale).width);
        l.labelWidth = widest + 2 * l.padding;
    }
    l.width = l.tileLeft(columns) - kGridGap;
    l.height = l.tileTop(rows) - kGridGap;
    return l;
}

Image assembleGrid(const std::vector<std::vector<const Image*>>& tiles, const PixelRect& crop,
                   const GridLabels& labels) {
    const int rows = int(tiles.size()), columns = tiles.empty() ? 0 : int(tiles[0].size());
    GridLayout l = gridLayout(rows, columns, crop.width, crop.height, labels);
    Image grid(l.width, l.height);
    std::fill(grid.pixels.begin(), grid.pixels.end(), kGridGapColour);
    for (int r = 0; r < rows; ++r) {
        if (int(tiles[size_t(r)].size()) != columns)
            throw Error("image grid: row " + std::to_string(r) + " has " +
                        std::to_string(tiles[size_t(r)].size()) + " tiles, row 0 has " +
                        std::to_string(columns));
        for (int c = 0; c < columns; ++c) {
            const Image& tile = *tiles[size_t(r)][size_t(c)];
            if (crop.x < 0 || crop.y < 0 || crop.x + crop.width > tile.width ||
                crop.y + crop.height > tile.height)
                throw Error("image grid: the crop is not inside the " + std::to_string(tile.width) + "x" +
                            std::to_string(tile.height) + " image at row " + std::to_string(r) + ", column " +
                            std::to_string(c));
            for (int y = 0; y < crop.height; ++y)
                for (int x = 0; x < crop.width; ++x)
                    grid.at(l.tileLeft(c) + x, l.tileTop(r) + y) = tile.at(crop.x + x, crop.y + y);
        }
    }
    for (int c = 0; c < int(labels.columns.size()); ++c) {
        const std::string& label = labels.columns[size_t(c)];
        int left = l.tileLeft(c) + std::max(0, (l.tileWidth - textExtent(label, l.scale).width) / 2);
        drawText(grid, label, left, l.padding, l.scale, labels.colour,
                 PixelRect{l.tileLeft(c), 0, l.tileWidth, l.headerHeight});
    }
    for (int r = 0; r < int(labels.rows.size()); ++r) {
        const std::string& label = labels.rows[size_t(r)];
        int top = l.tileTop(r) + std::max(0, (l.tileHeight - kTextRows * l.scale) / 2);
        drawText(grid, label, l.padding, top, l.scale, labels.colour,
                 PixelRect{0, 0, l.labelWidth, l.height});
    }
    return grid;
}

}  // namespace fp
