# `package require vfb` in a plain wish 8.6 (TCLLIBPATH points at the build folder):
# the loadable module, stubs-enabled, built from the same objects as vfbsh.
set version [package require vfb]
vfb .v -maxx 79 -maxy 59
pack .v
update
.v put_pixel 1 2 0 0 1 0
if {[lindex [.v get_pixel 1 2] 1] != 1.0} { error "put_pixel/get_pixel failed in the package" }
.v render scenes/sample.ray_trace
set p [.v wait]
if {[dict get $p state] ne "done"} { error "render: $p" }
puts "package vfb $version: widget, put/get and render work in [info nameofexecutable]"
exit 0
