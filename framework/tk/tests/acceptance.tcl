# Issue 4's acceptance check, run as `vfbsh acceptance.tcl OUT.png` under xvfb-run: create
# a 300 x 300 vfb, put and get a pixel, zoom, pan, save a readable image, exit 0. Any
# error exits non-zero (Tk_Main reports it and exits 1).
set out [lindex $argv 0]
vfb .v -maxx 299 -maxy 299
pack .v
update

.v put_pixel 10 20 0 1.0 0.5 0.25
lassign [.v get_pixel 10 20] r g b
if {abs($r - 1.0) > 0.01 || abs($g - 0.5) > 0.01 || abs($b - 0.25) > 0.01} {
    error "get_pixel 10 20 gave $r $g $b, not about 1.0 0.5 0.25"
}

.v zoom 8 100 100
if {[.v pixel_size] != 8} { error "zoom 8 left pixel_size at [.v pixel_size]" }
set before [.v virtual_x 100]
.v pan -80 0
if {[.v virtual_x 100] != $before + 10} { error "pan -80 0 at zoom 8 should move the view 10 pixels right" }
update

file delete $out
.v save $out
# Readable: a second buffer loads it and finds the pixel.
vfb .w -maxx 299 -maxy 299
.w load $out
lassign [.w get_pixel 10 20] r g b
if {abs($r - 1.0) > 0.01 || abs($g - 0.5) > 0.01 || abs($b - 0.25) > 0.01} {
    error "the saved image has $r $g $b at 10 20"
}
if {![catch {exec identify -format %m:%wx%h $out} what] && $what ne "PNG:300x300"} {
    error "identify says $what, not PNG:300x300"
}
puts "acceptance: put, get, zoom, pan and save ($out) work"
exit 0
