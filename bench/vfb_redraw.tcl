# The vfb widget's full-redraw benchmark; run it with bench/vfb_redraw (which starts a
# 4K Xvfb), or by hand: vfbsh bench/vfb_redraw.tcl ?repetitions?
#
# For each window and pixel size it times `.v redraw`: paint every pixel of the window
# and wait until the X server has it (XSync). "image" is the widget's drawing (one
# XImage, shared memory when the server allows); "rectangles" is the thesis's drawing,
# one X request per virtual pixel (-drawing rectangles -pixmap_drawing_on 0), and
# "stamps" its -pixmap_drawing_on 1 variant (a one-bit pixmap copied per pixel). Figures
# are medians in milliseconds. Grid and disks are on at the thesis's defaults (above 7).
set repetitions [expr {[llength $argv] ? [lindex $argv 0] : 25}]
set scene [file normalize [file join [file dirname [info script]] .. scenes sample.ray_trace]]
set tmp [file join [expr {[info exists env(TMPDIR)] ? $env(TMPDIR) : "/tmp"}] vfb-redraw-[pid]]
file mkdir $tmp

proc median_ms {script n} {
    set times {}
    for {set k 0} {$k < $n} {incr k} {
        set t0 [clock microseconds]
        uplevel 1 $script
        lappend times [expr {[clock microseconds] - $t0}]
    }
    set times [lsort -integer $times]
    return [expr {[lindex $times [expr {[llength $times] / 2}]] / 1000.0}]
}

proc measure {label width height} {
    wm geometry . ${width}x${height}+0+0
    update
    puts [format "%-22s %6s %10s %14s %10s" $label "size" "image" "rectangles" "stamps"]
    foreach size {1 2 8 16 32} {
        .v pixel_size $size
        .v configure -drawing image
        update
        set image [median_ms {.v redraw} $::repetitions]
        # The thesis's drawing takes up to seconds per frame: fewer runs.
        set slow_runs [expr {$size <= 2 ? 3 : 5}]
        .v configure -drawing rectangles -pixmap_drawing_on 0
        set rectangles [median_ms {.v redraw} $slow_runs]
        .v configure -pixmap_drawing_on 1
        set stamps [median_ms {.v redraw} $slow_runs]
        puts [format "%-22s %6s %10.2f %14.1f %10.1f" "" $size $image $rectangles $stamps]
    }
}

# The thesis's pictures were 875 x 700: render the sample scene at that size.
vfb .v -maxx 874 -maxy 699 -width 875 -height 700
pack .v -fill both -expand 1
wm geometry . 875x700+0+0
update
.v render $scene
.v wait
.v save [file join $tmp sample875.png]
puts "vfb redraw: median of $repetitions full redraws (ms), X server [winfo server .], screen [winfo screenwidth .]x[winfo screenheight .]"
measure "875 x 700 window" 875 700

# A 4K window full of pixels: the same picture scaled up by ImageMagick.
exec convert [file join $tmp sample875.png] -filter point -resize 3840x2160! [file join $tmp sample4k.png]
destroy .v
vfb .v -maxx 3839 -maxy 2159
pack .v -fill both -expand 1
.v load [file join $tmp sample4k.png]
measure "3840 x 2160 window" 3840 2160
file delete -force $tmp
exit 0
