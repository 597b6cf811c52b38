#!/bin/sh
# Demo: zoom into a pixel. The sample scene, then zoomed step by step to one virtual pixel
# on a sphere's edge: its coordinates, its colour and the intersection tests it cost.
#
#   build/default/framework/tk/vfbsh docs/demos/zoom-pixel.tcl     (or run this file)
#   xvfb-run -a -s "-screen 0 1280x1024x24" build/default/framework/tk/vfbsh docs/demos/zoom-pixel.tcl
#
# VL_DEMO_AUTOEXIT=1 runs it by itself and exits; VL_DEMO_SCREENSHOT=FILE writes a PNG of
# the window at the last step (docs/demos/lib/demo.tcl says more). \
root=$(dirname "$0")/../..; if [ -x "$root/build/default/framework/tk/vfbsh" ]; then exec "$root/build/default/framework/tk/vfbsh" "$0" "$@"; else exec vfbsh "$0" "$@"; fi

source [file join [file dirname [file normalize [info script]]] lib demo.tcl]

demo::setup "Zoom into a pixel"
set sample scenes/sample.ray_trace
set v [demo::pane sample "$sample (400 x 300 pixels, 4 jittered rays per pixel)" -maxx 399 -maxy 299 -width 560 -height 400]
# A swatch of the inspected pixel's colour, beside the note under the pane.
frame [winfo parent $v].swatch -width 40 -height 24 -background [ttk::style lookup TFrame -background]
pack [winfo parent $v].swatch -side left -before [winfo parent $v].note -padx {0 8}

# The pixel the demo zooms into: where column 175, read from the top down, leaves the
# background for the middle sphere's upper edge (a pixel whose rays partly hit it).
proc edge_pixel {v} {
    set x 175
    lassign [$v get_pixel $x [$v cget -maxy]] r0 g0 b0
    for {set y [$v cget -maxy]} {$y > 0} {incr y -1} {
        lassign [$v get_pixel $x $y] r g b
        if {abs($r - $r0) + abs($g - $g0) + abs($b - $b0) > 0.05} { return [list $x $y] }
    }
    demo::fail "no edge found in column $x of the sample scene: has scenes/sample.ray_trace changed?"
}

# Inspects the pixel in the middle of the window (where demo::zoom_to put the pixel) as a
# click on it would, and shows what the vfb script's status bar shows.
proc show_pixel {v} {
    update idletasks
    set info [$v inspect {*}[demo::centre $v]]
    demo::note $v [demo::describe $info]
    [winfo parent $v].swatch configure -background [dict get $info srgb]
    set ::demo::status "inspect: [demo::describe $info]"
    return $info
}

demo::step "The sample scene" \
"Three spheres on a huge one, coloured by their normals. At one screen pixel per virtual pixel the\
edges look smooth enough: each pixel is the average of 4 rays at random places inside it." {
    demo::render $v [demo::path $sample]
}

demo::step "8 screen pixels per virtual pixel: the grid and the disks" \
"Zoomed about a pixel on the middle sphere's upper edge. Above 7 screen pixels per virtual pixel (the thesis's\
-grid_on_at 7 and -disk_on_at 7) every virtual pixel is drawn as a disk inside a grid, so one can count them:\
the edge is a staircase, and the pixels on it are mixtures of sphere and sky." {
    lassign [edge_pixel $v] ::x ::y
    demo::zoom_to $v 8 $::x $::y
    show_pixel $v
}

demo::step "32 screen pixels per virtual pixel" \
"The same pixel in the middle of the window. Each disk has one colour: a pixel is a sample of the picture,\
not a little square of it. Its neighbours above are sky, below sphere; it is in between." {
    demo::zoom_to $v 32 $::x $::y
    show_pixel $v
}

demo::step "One virtual pixel" \
"256 screen pixels per virtual pixel, the most the widget zooms: one pixel fills the middle of the window.\
Below the picture is what a click on it shows (the vfb script's status bar): its coordinates (0, 0 is the lower\
left), its colour as sRGB and in linear light, and the intersection tests its rays cost: 4 rays, each tested\
against the scene's LIST and its 4 spheres, 4 x (1 + 4) = 20. With a LIST every pixel costs the same." {
    demo::zoom_to $v 256 $::x $::y
    set info [show_pixel $v]
    if {[dict get $info x] != $::x || [dict get $info y] != $::y} {
        demo::fail "the middle of the window shows pixel ([dict get $info x], [dict get $info y]), not ($::x, $::y)"
    }
    if {[dict get $info tests] ne "20"} {
        demo::fail "pixel ($::x, $::y) cost [dict get $info tests] tests, not the 20 the caption explains:\
            has scenes/sample.ray_trace changed? Update the caption."
    }
}

demo::start
