#include "zoom_painter.hh"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace vl::tk {

rect rect::united(const rect& r) const {
    if (r.empty()) return *this;
    if (empty()) return r;
    return {std::min(x0, r.x0), std::min(y0, r.y0), std::max(x1, r.x1), std::max(y1, r.y1)};
}

rect rect::clipped(const rect& r) const {
    return {std::max(x0, r.x0), std::max(y0, r.y0), std::min(x1, r.x1), std::min(y1, r.y1)};
}

rect zoom_painter::to_screen(const rect& r, const view& v, int screen_height) {
    const int ps = v.pixel_size;
    // Rows count up from the bottom in virtual space and down from the top on screen.
    return {v.origin_x + r.x0 * ps, screen_height - (v.origin_y + r.y1 * ps), v.origin_x + r.x1 * ps,
            screen_height - (v.origin_y + r.y0 * ps)};
}

// The disk inscribed in an inner x inner square, by the midpoint rule: column i of row j
// is inside when its centre (i + 0.5, j + 0.5) is within inner / 2 of the square's centre.
void zoom_painter::make_disk(int inner) {
    if (inner == disk_inner_) return;
    disk_inner_ = inner;
    disk_.assign(static_cast<std::size_t>(inner), {0, 0});
    const double r = inner / 2.0;
    for (int j = 0; j < inner; ++j) {
        const double dy = j + 0.5 - r;
        const double half = std::sqrt(std::max(0.0, r * r - dy * dy));
        const int first = static_cast<int>(std::ceil(r - half - 0.5));
        const int last = static_cast<int>(std::floor(r + half - 0.5));  // inclusive
        disk_[static_cast<std::size_t>(j)] = first <= last ? std::pair{first, last + 1} : std::pair{0, 0};
    }
}

// A row without grid or disks: background, then pixel_size copies of each colour (a
// straight copy at pixel size 1), then background. `out` points at screen column 0.
void zoom_painter::paint_plain_row(const std::uint32_t* row, int buffer_width, const view& v, std::uint32_t* out,
                                   const rect& area, std::uint32_t background) {
    const int ps = v.pixel_size;
    const int left = std::clamp(v.origin_x, area.x0, area.x1);                       // buffer's left edge
    const int right = std::clamp(v.origin_x + buffer_width * ps, area.x0, area.x1);  // and right edge
    std::fill_n(out + area.x0, left - area.x0, background);
    std::fill_n(out + right, area.x1 - right, background);
    if (left >= right) return;
    if (ps == 1) {
        std::memcpy(out + left, row + (left - v.origin_x), static_cast<std::size_t>(right - left) * sizeof(std::uint32_t));
        return;
    }
    int vx = (left - v.origin_x) / ps;
    int sx = left;
    const int first_end = std::min(v.origin_x + (vx + 1) * ps, right);  // the first cell may be cut
    std::fill_n(out + sx, first_end - sx, row[vx]);
    for (sx = first_end, ++vx; sx + ps <= right; sx += ps, ++vx) std::fill_n(out + sx, ps, row[vx]);
    if (sx < right) std::fill_n(out + sx, right - sx, row[vx]);
}

void zoom_painter::paint(std::span<const std::uint32_t> colors, int buffer_width, int buffer_height,
                         const view& v, const paint_style& style, std::uint32_t* screen, int stride,
                         int screen_width, int screen_height, rect area) {
    area = area.clipped({0, 0, screen_width, screen_height});
    if (area.empty()) return;
    const int ps = v.pixel_size;
    const bool grid = style.grid && ps >= min_grid_size;
    const bool disks = style.disks && ps >= min_disk_size;
    const int inner = grid ? ps - 1 : ps;  // the grid takes the top row and left column
    if (disks) make_disk(inner);
    const int width = area.x1 - area.x0;

    // A screen row is fixed by its virtual row and the span of the disk it cuts (a disk's
    // rows come in equal pairs, top and bottom, and the middle rows are equal too), so a
    // row already painted for the same virtual row and span is copied, not painted again.
    constexpr int grid_row = -1, outside = -2;
    int current_vy = 0;
    bool have_row = false;
    std::vector<int>& painted = painted_rows_;  // painted[first + 2]: a screen row, or -1
    painted.assign(static_cast<std::size_t>(inner) + 3, -1);

    for (int sy = area.y0; sy < area.y1; ++sy) {
        std::uint32_t* out = screen + static_cast<std::ptrdiff_t>(sy) * stride + area.x0;
        const int up = screen_height - 1 - sy - v.origin_y;  // rows up from virtual row 0's bottom
        const int vy = floor_div(up, ps);
        const int from_top = ps - 1 - (up - vy * ps);        // 0 is the cell's top row
        int key = outside;  // which kind of row: outside, grid_row, or the span's first column
        std::pair<int, int> span{0, inner};
        if (vy >= 0 && vy < buffer_height) {
            if (grid && from_top == 0) {
                key = grid_row;
            } else {
                if (disks) span = disk_[static_cast<std::size_t>(from_top - (grid ? 1 : 0))];
                key = span.first;
            }
        }
        if (!have_row || vy != current_vy) {
            std::fill(painted.begin(), painted.end(), -1);
            current_vy = vy;
            have_row = true;
        }
        int& earlier = painted[static_cast<std::size_t>(key + 2)];
        if (earlier >= 0) {
            std::memcpy(out, screen + static_cast<std::ptrdiff_t>(earlier) * stride + area.x0,
                        static_cast<std::size_t>(width) * sizeof(std::uint32_t));
            continue;
        }
        earlier = sy;
        if (key == outside) {
            std::fill_n(out, width, style.background);
            continue;
        }
        const std::uint32_t* row = colors.data() + static_cast<std::ptrdiff_t>(vy) * buffer_width;
        if (!grid && !disks) {
            paint_plain_row(row, buffer_width, v, out - area.x0, area, style.background);
            continue;
        }
        // Every cell of this row has the same shape: a template of pixel_size entries says,
        // per column, either "a fixed colour" (grid or background) or "the pixel's colour",
        // as out = (colour & mask) | fixed, which has no branch and vectorises.
        cell_mask_.assign(static_cast<std::size_t>(ps), 0);
        cell_fixed_.assign(static_cast<std::size_t>(ps), style.background);
        for (int i = 0; i < ps; ++i) {
            const int inner_i = i - (grid ? 1 : 0);
            if (key == grid_row || (grid && i == 0)) {
                cell_fixed_[static_cast<std::size_t>(i)] = style.grid_color;
            } else if (inner_i >= span.first && inner_i < span.second) {
                cell_mask_[static_cast<std::size_t>(i)] = ~std::uint32_t{0};
                cell_fixed_[static_cast<std::size_t>(i)] = 0;
            }
        }
        const std::uint32_t* mask = cell_mask_.data();
        const std::uint32_t* fixed = cell_fixed_.data();
        std::uint32_t* line = screen + static_cast<std::ptrdiff_t>(sy) * stride;
        const int left = std::clamp(v.origin_x, area.x0, area.x1);                       // buffer's left edge
        const int right = std::clamp(v.origin_x + buffer_width * ps, area.x0, area.x1);  // and right edge
        std::fill_n(line + area.x0, left - area.x0, style.background);
        std::fill_n(line + right, area.x1 - right, style.background);
        int sx = left;
        while (sx < right) {
            const int vx = floor_div(sx - v.origin_x, ps);
            const int cell_left = v.origin_x + vx * ps;
            const std::uint32_t color = row[vx];
            if (sx == cell_left && cell_left + ps <= right) {  // a whole cell
                std::uint32_t* o = line + cell_left;
                for (int i = 0; i < ps; ++i) o[i] = (color & mask[i]) | fixed[i];
                sx += ps;
            } else {  // a cell cut by the area's edge
                const int end = std::min(cell_left + ps, right);
                for (; sx < end; ++sx) line[sx] = (color & mask[sx - cell_left]) | fixed[sx - cell_left];
            }
        }
    }
}

}  // namespace vl::tk
