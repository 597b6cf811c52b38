#!/bin/sh
# Demo: render live. The stage 04 room appears in the vfb tile by tile while the window
# keeps answering: zoom into it during the render, cancel one half-way.
#
#   build/default/framework/tk/vfbsh docs/demos/render-live.tcl     (or run this file)
#   xvfb-run -a -s "-screen 0 1280x1024x24" build/default/framework/tk/vfbsh docs/demos/render-live.tcl
#
# VL_DEMO_AUTOEXIT=1 runs it by itself and exits; VL_DEMO_SCREENSHOT=FILE writes a PNG of
# the window half-way through the slow render (docs/demos/lib/demo.tcl says more). \
root=$(dirname "$0")/../..; if [ -x "$root/build/default/framework/tk/vfbsh" ]; then exec "$root/build/default/framework/tk/vfbsh" "$0" "$@"; else exec vfbsh "$0" "$@"; fi

source [file join [file dirname [file normalize [info script]]] lib demo.tcl]

demo::setup "Render live"
set room assignments/04-shading/scenes/room.ray_trace
set v [demo::pane room "$room (400 x 320 pixels)" -maxx 399 -maxy 319]
# The same room with 128 rays per pixel: about 60 times the work, so the tiles can be seen.
set slow [demo::derived_scene $room room-128-rays.ray_trace [list \
    {^samples .*$} "samples [demo::rays 128]" \
    {^sampler .*$} {sampler jittered}]]
demo::screenshot_at manual

# Takes the screenshot once a slow render is 42 % done (mid-way through a row of tiles).
proc shoot_half_way {p} {
    if {[dict get $p state] eq "running" && [dict get $p fraction] >= 0.42} { demo::shoot }
}

demo::step "The scene as the handout ships it" \
"rt and the vfb render a scene the same way: the framework's render driver. With 2 rays per pixel this room\
takes a fraction of a second: too fast to see how the picture is made. (The time is under the picture.)" {
    demo::render $v [demo::path $room]
}

demo::step "The same room with 128 rays per pixel: watch the tiles" \
"The image is cut into tiles of 16 x 16 pixels. Each worker thread (one per core) takes the next tile, traces\
its pixels one by one, row by row, and hands the finished tile over. The tiles fill in from the bottom row up,\
left to right: (0, 0) is the lower-left pixel, as in the thesis's vfb. The render thread never touches the\
window; a 16 ms timer in the user interface copies the finished tiles onto the screen." {
    demo::render $v $slow shoot_half_way
}

demo::step "Zoom while it renders" \
"The same render again, and after half a second the view zooms to 4 screen pixels per virtual pixel about the\
middle of the room: the window keeps answering, because the tracing runs in the background. Turn the mouse\
wheel or drag to pan while the tiles arrive." {
    $v pixel_size 1
    $v set_min_x 0
    $v set_min_y 0
    demo::render $v $slow shoot_half_way
    after 500 [list demo::zoom_to $v 4 200 160]
}

demo::step "Cancel half-way" \
"Escape (in the vfb script) or the widget's cancel stops the workers after their current tile: the finished\
tiles stay, the rest of the buffer keeps what it had (here: black)." {
    demo::zoom_to $v 1 0 0
    $v set_min_x 0
    $v set_min_y 0
    demo::render $v $slow [list apply {{v p} {
        if {[dict get $p state] eq "running" && [dict get $p fraction] >= 0.5} { $v cancel }
    }} $v]
}

demo::start
