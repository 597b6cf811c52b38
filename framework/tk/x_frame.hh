#pragma once
/// \file
/// \brief A window-sized XImage the widget paints into and puts on the screen in one request.

#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/extensions/XShm.h>

#include <cstdint>

#include "zoom_painter.hh"

namespace vl::tk {

/// \brief Client-side pixels for a window, sent to the X server with XShmPutImage when the
/// server shares memory with us (a local display) and XPutImage otherwise.
///
/// Only 32-bit TrueColor pixels are handled (what every X server of the last twenty years
/// offers); supported() says whether this display has them.
class x_frame {
public:
    x_frame(Display* display, Visual* visual, int depth);
    ~x_frame();
    x_frame(const x_frame&) = delete;
    x_frame& operator=(const x_frame&) = delete;

    /// True if the visual is 24- or 32-bit TrueColor.
    bool supported() const { return supported_; }
    /// True if the last resize() got a shared-memory image.
    bool shared() const { return shm_attached_; }
    /// Makes the image `width` x `height`; its contents are undefined until painted.
    void resize(int width, int height);
    int width() const { return width_; }   ///< Pixels per row.
    int height() const { return height_; } ///< Rows.
    /// The pixels, top row first, width() per row.
    std::uint32_t* pixels() { return pixels_; }
    /// An 8-bit sRGB colour in this visual's pixel format.
    std::uint32_t pack(std::uint8_t r, std::uint8_t g, std::uint8_t b) const;
    /// Copies `area` of the image to the same place in `target`.
    void put(Drawable target, GC gc, rect area);

private:
    void release();

    Display* display_;
    Visual* visual_;
    int depth_;
    bool supported_ = false;
    int shift_[3] = {0, 0, 0}, bits_[3] = {8, 8, 8};
    int width_ = 0, height_ = 0;
    XImage* image_ = nullptr;
    std::uint32_t* pixels_ = nullptr;
    XShmSegmentInfo shm_{};
    bool shm_attached_ = false;
};

}  // namespace vl::tk
