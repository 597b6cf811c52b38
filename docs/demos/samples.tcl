#!/bin/sh
# Demo: 1 against 4 rays per pixel. The sample scene side by side, once with one ray
# through each pixel's centre, once with 4 on a 2 x 2 grid, then both zoomed onto the same
# sphere edge: a staircase on the left, in-between shades on the right.
#
#   build/default/framework/tk/vfbsh docs/demos/samples.tcl     (or run this file)
#   xvfb-run -a -s "-screen 0 1280x1024x24" build/default/framework/tk/vfbsh docs/demos/samples.tcl
#
# VL_DEMO_AUTOEXIT=1 runs it by itself and exits; VL_DEMO_SCREENSHOT=FILE writes a PNG of
# the window at the last step (docs/demos/lib/demo.tcl says more). \
root=$(dirname "$0")/../..; if [ -x "$root/build/default/framework/tk/vfbsh" ]; then exec "$root/build/default/framework/tk/vfbsh" "$0" "$@"; else exec vfbsh "$0" "$@"; fi

source [file join [file dirname [file normalize [info script]]] lib demo.tcl]

demo::setup "1 against 4 rays per pixel"
set sample scenes/sample.ray_trace
set one [demo::derived_scene $sample sample-1-ray.ray_trace {{^samples .*$} {samples 1} {^sampler .*$} {sampler center}}]
set four [demo::derived_scene $sample sample-4-rays.ray_trace {{^samples .*$} {samples 4} {^sampler .*$} {sampler grid}}]
set a [demo::pane one "1 ray per pixel (sampler center)" -maxx 399 -maxy 299]
set b [demo::pane four "4 rays per pixel (sampler grid, 2 x 2)" -maxx 399 -maxy 299]

demo::step "The same scene, 1 and 4 rays per pixel" \
"Left: one ray through the centre of each pixel. Right: four rays on a 2 x 2 grid inside each pixel, averaged.\
At this size the difference is already visible on the spheres' outlines: the left ones are ragged." {
    demo::render $a $one
    demo::render $b $four
}

demo::step "Zoomed onto the same edge: aliasing" \
"Both at 8 screen pixels per virtual pixel, on the upper left edge of the middle sphere. With one ray a pixel is\
either sphere or sky: the edge is a staircase (aliasing). With four rays a pixel on the edge is 1/4, 2/4 or 3/4\
sphere, so the staircase has in-between steps and looks smooth from afar. Four times the rays, four times the time." {
    demo::zoom_to $a 8 170 212
    demo::zoom_to $b 8 170 212
}

demo::start
