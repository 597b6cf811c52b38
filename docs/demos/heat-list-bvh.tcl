#!/bin/sh
# Demo: the heat map of a LIST against a BVH. Stage 03's 2024 spheres, once in a LIST and
# once in a BVH, side by side: the picture, then the intersection tests per pixel.
#
#   build/default/framework/tk/vfbsh docs/demos/heat-list-bvh.tcl     (or run this file)
#   xvfb-run -a -s "-screen 0 1280x1024x24" build/default/framework/tk/vfbsh docs/demos/heat-list-bvh.tcl
#
# VL_DEMO_AUTOEXIT=1 runs it by itself and exits; VL_DEMO_SCREENSHOT=FILE writes a PNG of
# the window at the last step (docs/demos/lib/demo.tcl says more). \
root=$(dirname "$0")/../..; if [ -x "$root/build/default/framework/tk/vfbsh" ]; then exec "$root/build/default/framework/tk/vfbsh" "$0" "$@"; else exec vfbsh "$0" "$@"; fi

source [file join [file dirname [file normalize [info script]]] lib demo.tcl]

demo::setup "Heat map: a LIST against a BVH"
set bvh_scene assignments/03-composites/scenes/bvh.ray_trace
# One ray per pixel (the heat is the same, the LIST render 4 times faster); the LIST copy
# only replaces "BVH { leaf_size 4" by "LIST {".
set bvh [demo::derived_scene $bvh_scene bvh-1-ray.ray_trace {{^samples .*$} {samples 1} {^sampler .*$} {sampler center}}]
set list [demo::derived_scene $bvh_scene list-1-ray.ray_trace [list {^samples .*$} {samples 1} {^sampler .*$} {sampler center} {^BVH \{ leaf_size 4} "LIST \{"]]
set a [demo::pane list "LIST { 2024 spheres }" -maxx 319 -maxy 239]
set b [demo::pane bvh "BVH { leaf_size 4  2024 spheres }" -maxx 319 -maxy 239]

demo::step "2024 spheres in a LIST and in a BVH" \
"The same spheres of $bvh_scene, one ray per pixel, coloured by their normals. The pictures are the same:\
a composite changes what a ray costs, never what it sees. Compare the render times under the pictures." {
    demo::render $a $list
    demo::render $b $bvh
}

demo::step "The heat map: intersection tests per pixel" \
"Each pixel coloured by the tests its ray cost, black (fewest) through red and yellow to white (most); each map is\
scaled to its own largest count, so read the numbers under them. The LIST tests all 2024 spheres for every ray:\
uniform. The BVH tests boxes first: cheap where rays pass through empty space, hot on the silhouettes and where\
many spheres overlap along the ray." {
    foreach v [list $a $b] {
        $v configure -view heat
        lassign [demo::test_counts $v 2] mean most
        demo::note $v [format "tests per pixel: mean %.0f, most %d" $mean $most]
    }
}

demo::start
