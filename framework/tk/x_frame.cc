#include "x_frame.hh"

#include <sys/ipc.h>
#include <sys/shm.h>
#include <tk.h>

#include <bit>
#include <cstdlib>
#include <new>

namespace vl::tk {

namespace {

// Counts the X errors a request caused (Tk_CreateErrorHandler calls it instead of aborting).
int note_x_error(ClientData flag, XErrorEvent*) {
    *static_cast<bool*>(flag) = true;
    return 0;
}

}  // namespace

x_frame::x_frame(Display* display, Visual* visual, int depth) : display_(display), visual_(visual), depth_(depth) {
    const unsigned long masks[3] = {visual->red_mask, visual->green_mask, visual->blue_mask};
    supported_ = (visual->c_class == TrueColor || visual->c_class == DirectColor) && (depth == 24 || depth == 32);
    for (int c = 0; c < 3; ++c) {
        shift_[c] = masks[c] ? std::countr_zero(masks[c]) : 0;
        bits_[c] = std::popcount(masks[c]);
        if (bits_[c] < 1 || bits_[c] > 8) supported_ = false;
    }
}

x_frame::~x_frame() { release(); }

std::uint32_t x_frame::pack(std::uint8_t r, std::uint8_t g, std::uint8_t b) const {
    const std::uint8_t v[3] = {r, g, b};
    std::uint32_t p = 0;
    for (int c = 0; c < 3; ++c) p |= static_cast<std::uint32_t>(v[c] >> (8 - bits_[c])) << shift_[c];
    return p;
}

void x_frame::release() {
    if (!image_) return;
    if (shm_attached_) {
        XShmDetach(display_, &shm_);
        XSync(display_, False);  // the server lets go of the segment before we do
        image_->data = nullptr;
        XDestroyImage(image_);
        shmdt(shm_.shmaddr);
        shm_attached_ = false;
    } else {
        image_->data = nullptr;  // ours, not Xlib's: freed below
        XDestroyImage(image_);
        std::free(pixels_);
    }
    image_ = nullptr;
    pixels_ = nullptr;
    width_ = height_ = 0;
}

void x_frame::resize(int width, int height) {
    if (width == width_ && height == height_ && image_) return;
    release();
    if (!supported_ || width < 1 || height < 1) return;
    const std::size_t bytes = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4;

    // Shared memory first: the server reads the pixels where we wrote them, no copy
    // through the socket (for a 4K window that is 33 MB per redraw).
    if (XShmQueryExtension(display_)) {
        image_ = XShmCreateImage(display_, visual_, static_cast<unsigned>(depth_), ZPixmap, nullptr, &shm_,
                                 static_cast<unsigned>(width), static_cast<unsigned>(height));
        if (image_ && image_->bits_per_pixel == 32 && image_->bytes_per_line == width * 4) {
            shm_.shmid = shmget(IPC_PRIVATE, bytes, IPC_CREAT | 0600);
            if (shm_.shmid >= 0) {
                shm_.shmaddr = static_cast<char*>(shmat(shm_.shmid, nullptr, 0));
                shm_.readOnly = False;
                bool failed = shm_.shmaddr == reinterpret_cast<char*>(-1);
                if (!failed) {
                    // A remote server cannot attach: it answers with an error, caught here.
                    Tk_ErrorHandler h = Tk_CreateErrorHandler(display_, -1, -1, -1, note_x_error, &failed);
                    XShmAttach(display_, &shm_);
                    XSync(display_, False);
                    Tk_DeleteErrorHandler(h);
                }
                shmctl(shm_.shmid, IPC_RMID, nullptr);  // freed when the last user detaches
                if (!failed) {
                    image_->data = shm_.shmaddr;
                    pixels_ = reinterpret_cast<std::uint32_t*>(shm_.shmaddr);
                    shm_attached_ = true;
                } else if (shm_.shmaddr != reinterpret_cast<char*>(-1)) {
                    shmdt(shm_.shmaddr);
                }
            }
        }
        if (!shm_attached_ && image_) {
            image_->data = nullptr;
            XDestroyImage(image_);
            image_ = nullptr;
        }
    }
    if (!image_) {
        pixels_ = static_cast<std::uint32_t*>(std::malloc(bytes));
        if (!pixels_) throw std::bad_alloc();
        image_ = XCreateImage(display_, visual_, static_cast<unsigned>(depth_), ZPixmap, 0,
                              reinterpret_cast<char*>(pixels_), static_cast<unsigned>(width),
                              static_cast<unsigned>(height), 32, width * 4);
        if (!image_ || image_->bits_per_pixel != 32) {
            if (image_) {
                image_->data = nullptr;
                XDestroyImage(image_);
                image_ = nullptr;
            }
            std::free(pixels_);
            pixels_ = nullptr;
            supported_ = false;
            return;
        }
    }
    // We write native 32-bit values; Xlib swaps them if the server wants the other order.
    image_->byte_order = std::endian::native == std::endian::little ? LSBFirst : MSBFirst;
    width_ = width;
    height_ = height;
}

void x_frame::put(Drawable target, GC gc, rect area) {
    area = area.clipped({0, 0, width_, height_});
    if (!image_ || area.empty()) return;
    const auto w = static_cast<unsigned>(area.x1 - area.x0), h = static_cast<unsigned>(area.y1 - area.y0);
    if (shm_attached_) {
        XShmPutImage(display_, target, gc, image_, area.x0, area.y0, area.x0, area.y0, w, h, False);
        XSync(display_, False);  // the server has read the pixels before we paint the next frame
    } else {
        XPutImage(display_, target, gc, image_, area.x0, area.y0, area.x0, area.y0, w, h);
    }
}

}  // namespace vl::tk
