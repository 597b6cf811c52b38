# The vfb widget's class bindings, evaluated by Vfb_Init (so vfbsh and `package require
# vfb` behave the same): the mouse wheel zooms about the cursor, dragging with button 1
# or 2 pans, and a click of button 1 (without a drag) inspects the pixel under it and
# calls the widget's -inspectcommand with what `inspect` returned.

namespace eval ::vfb {
    # Pixel sizes the wheel steps through.
    variable zoom_steps {1 2 3 4 5 6 8 10 12 16 20 24 32 48 64 96 128 192 256}
    # Per widget: the last pointer position and whether the button moved far enough to
    # be a drag rather than a click.
    variable drag
}

# Zooms widget w one step in (direction 1) or out (-1), keeping the pixel under (x, y);
# returns the new pixel size. Afterwards it sends w the virtual event <<Zoomed>>, so a
# zoom label bound to it shows the new size (a plain <Button-4> binding on w runs before
# this class binding and would see the old one).
proc ::vfb::zoom_step {w direction x y} {
    variable zoom_steps
    set size [$w pixel_size]
    set new $size
    if {$direction > 0} {
        foreach s $zoom_steps { if {$s > $size} { set new $s; break } }
    } else {
        foreach s [lreverse $zoom_steps] { if {$s < $size} { set new $s; break } }
    }
    if {$new != $size} { set new [$w zoom $new $x $y] }
    event generate $w <<Zoomed>>
    return $new
}

proc ::vfb::press {w x y} {
    variable drag
    set drag($w) [list $x $y 0]
}

# A drag pans once the pointer has moved 3 pixels, so that a click may wobble.
proc ::vfb::motion {w x y} {
    variable drag
    if {![info exists drag($w)]} return
    lassign $drag($w) px py moved
    if {!$moved && abs($x - $px) + abs($y - $py) < 3} return
    $w pan [expr {$x - $px}] [expr {$y - $py}]
    set drag($w) [list $x $y 1]
}

proc ::vfb::release {w x y} {
    variable drag
    if {![info exists drag($w)]} return
    set moved [lindex $drag($w) 2]
    unset drag($w)
    if {!$moved} { ::vfb::inspect $w $x $y }
}

# Inspects the pixel at (x, y) and hands the result to -inspectcommand.
proc ::vfb::inspect {w x y} {
    set info [$w inspect $x $y]
    set command [$w cget -inspectcommand]
    if {$command ne ""} { uplevel #0 [linsert $command end $info] }
    return $info
}

bind Vfb <Button-4> {::vfb::zoom_step %W 1 %x %y}
bind Vfb <Button-5> {::vfb::zoom_step %W -1 %x %y}
bind Vfb <MouseWheel> {::vfb::zoom_step %W [expr {%D > 0 ? 1 : -1}] %x %y}
bind Vfb <ButtonPress-1> {::vfb::press %W %x %y}
bind Vfb <B1-Motion> {::vfb::motion %W %x %y}
bind Vfb <ButtonRelease-1> {::vfb::release %W %x %y}
bind Vfb <ButtonPress-2> {set ::vfb::drag(%W) [list %x %y 1]}
bind Vfb <B2-Motion> {::vfb::motion %W %x %y}
bind Vfb <ButtonRelease-2> {unset -nocomplain ::vfb::drag(%W)}
bind Vfb <Destroy> {unset -nocomplain ::vfb::drag(%W)}
