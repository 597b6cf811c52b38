# What the demos in docs/demos/ share: the window (a caption above, the demo's panes, a
# bar with Next and Quit below), the steps, temporary scene files, the screenshot and
# the automatic exit. A demo sources this file, adds its panes and its steps, and calls
# demo::start:
#
#   source [file join [file dirname [file normalize [info script]]] lib demo.tcl]
#   demo::setup "Render live"
#   set v [demo::pane left "A title" -maxx 399 -maxy 299]
#   demo::step "What the students see now" { $v render [demo::path scenes/sample.ray_trace] }
#   demo::start
#
# Each step runs its script, shows its caption and waits for the renders it started; the
# TA then presses Next (or Space, Return, the right arrow). q or Escape quits.
#
# The environment:
#   VL_DEMO_AUTOEXIT=1         run every step by itself, one short pause apart, and exit
#                              (status 0; 1 when a step fails; 3 when it takes too long)
#   VL_DEMO_SCREENSHOT=FILE    write a PNG of the window at the demo's screenshot step
#                              (the last one unless the demo says otherwise)
#   VL_DEMO_PAUSE_MS=N         the pause between steps with VL_DEMO_AUTOEXIT (default 300)
#   VL_DEMO_TIMEOUT_S=N        with VL_DEMO_AUTOEXIT, give up (status 3) after N seconds
#                              (default 120)
#   VL_DEMO_FAST=1             slow renders trace a sixteenth of their rays (demo::rays):
#                              the tests set it, so that a sanitizer build finishes in time

namespace eval ::demo {
    # The repository: this file is docs/demos/lib/demo.tcl.
    variable root [file dirname [file dirname [file dirname [file dirname [file normalize [info script]]]]]]
    variable name ""
    variable script ""
    variable steps {}
    variable current -1
    variable panes {}
    variable auto [expr {[info exists ::env(VL_DEMO_AUTOEXIT)] && $::env(VL_DEMO_AUTOEXIT) ni {"" 0}}]
    variable screenshot [expr {[info exists ::env(VL_DEMO_SCREENSHOT)] ? $::env(VL_DEMO_SCREENSHOT) : ""}]
    variable screenshot_step -1
    variable pause_ms [expr {[info exists ::env(VL_DEMO_PAUSE_MS)] ? $::env(VL_DEMO_PAUSE_MS) : 300}]
    variable timeout_s [expr {[info exists ::env(VL_DEMO_TIMEOUT_S)] ? $::env(VL_DEMO_TIMEOUT_S) : 120}]
    variable fast [expr {[info exists ::env(VL_DEMO_FAST)] && $::env(VL_DEMO_FAST) ni {"" 0}}]
    variable temp_dir ""
    variable caption_title ""
    variable caption_text ""
    variable status ""
}

# The vfb widget: built into vfbsh; in another wish, the package beside the default build's vfbsh.
if {[info commands vfb] eq ""} {
    lappend auto_path [file join $::demo::root build default framework tk]
    if {[catch {package require vfb} message]} {
        puts stderr "[info script]: the vfb widget is not available ($message).\
            Run the demo with vfbsh: build it with `cmake --build build/default --target vfbsh`,\
            then run build/default/framework/tk/vfbsh [info script]"
        exit 1
    }
}

# A path in the repository, from its root: demo::path scenes/sample.ray_trace.
proc ::demo::path {relative} {
    variable root
    set p [file join $root $relative]
    if {![file exists $p]} { demo::fail "$p is missing: the demo needs it (is the repository complete?)" }
    return $p
}

# Stops the demo with a message naming the demo script and its current step.
proc ::demo::fail {message} {
    variable script
    variable current
    variable auto
    set where $script
    if {$current >= 0} { append where ": step [expr {$current + 1}]" }
    puts stderr "$where: $message"
    if {$auto || ![winfo exists .]} { demo::cleanup; exit 1 }
    tk_messageBox -icon error -title "Virtual Light demo" -message "$where: $message"
}

# A background error (in a step, a timer or a binding) is a failure of the demo.
proc ::bgerror {message} {
    demo::fail "$message\n$::errorInfo"
}

proc ::demo::setup {title} {
    variable name $title
    # Called from the demo's top level, after this file was sourced: the demo's file.
    variable script [file tail [info script]]
    wm title . "Virtual Light demo: $title"
    ttk::style configure Caption.TLabel -font {Helvetica 15 bold}
    ttk::style configure Text.TLabel -font {Helvetica 12}
    ttk::style configure Pane.TLabel -font {Helvetica 11}
    ttk::frame .caption -padding {10 8 10 4}
    ttk::label .caption.title -textvariable ::demo::caption_title -style Caption.TLabel -anchor w
    ttk::label .caption.text -textvariable ::demo::caption_text -style Text.TLabel -anchor w \
        -justify left -wraplength 1000
    pack .caption.title .caption.text -side top -fill x -anchor w
    pack .caption -side top -fill x
    ttk::frame .panes -padding {10 4}
    pack .panes -side top -fill both -expand 1
    ttk::frame .bar -padding {10 4 10 8}
    ttk::label .bar.status -textvariable ::demo::status -anchor w -font TkFixedFont
    ttk::button .bar.quit -text Quit -command demo::quit
    ttk::button .bar.next -text "Next \u2192" -command demo::next
    pack .bar.quit .bar.next -side right -padx 4
    pack .bar.status -side left -fill x -expand 1
    pack .bar -side bottom -fill x
    bind . <space> demo::next
    bind . <Return> demo::next
    bind . <Right> demo::next
    bind . <Key-q> demo::quit
    bind . <Escape> demo::quit
    wm protocol . WM_DELETE_WINDOW demo::quit
}

# Adds a pane: a title above a new vfb widget (options as for vfb). Returns the widget.
proc ::demo::pane {id title args} {
    variable panes
    set f .panes.$id
    ttk::frame $f -padding 4
    ttk::label $f.title -text $title -style Pane.TLabel -anchor w -justify left
    ttk::label $f.note -style Pane.TLabel -anchor w -justify left -font TkFixedFont
    vfb $f.v {*}$args
    pack $f.title -side top -fill x
    pack $f.v -side top
    pack $f.note -side top -fill x
    pack $f -side left -anchor n -padx 4
    lappend panes $f.v
    return $f.v
}

# The line of text under a pane's widget.
proc ::demo::note {v text} { [winfo parent $v].note configure -text $text }
proc ::demo::title {v text} { [winfo parent $v].title configure -text $text }

# Adds a step: its caption (a title, then what to say) and the script it runs.
proc ::demo::step {title text script} {
    variable steps
    lappend steps [list $title $text $script]
}

# The step after which the screenshot is taken (by default the last), counting from 1;
# `manual`: none after a step, the demo calls demo::shoot itself (during a render, say).
proc ::demo::screenshot_at {n} {
    variable screenshot_step [expr {$n eq "manual" ? -2 : $n - 1}]
}

# Takes the screenshot now if one was asked for and not yet taken.
proc ::demo::shoot {} {
    variable screenshot
    if {$screenshot eq ""} return
    demo::take_screenshot $screenshot
    set screenshot ""
}

# The rays per pixel for a render meant to be slow: n, or with VL_DEMO_FAST n / 16 (at least 1).
proc ::demo::rays {n} {
    variable fast
    return [expr {$fast ? max(1, $n / 16) : $n}]
}

# Writes a scene file in the demo's temporary folder and returns its path.
proc ::demo::scene_file {name text} {
    variable temp_dir
    if {$temp_dir eq ""} {
        set base [expr {[info exists ::env(TMPDIR)] && $::env(TMPDIR) ne "" ? $::env(TMPDIR) : "/tmp"}]
        set temp_dir [file join $base vl-demo-[pid]]
        file mkdir $temp_dir
    }
    set file [file join $temp_dir $name]
    set ch [open $file w]
    puts -nonewline $ch $text
    close $ch
    return $file
}

# A copy of the repository's scene `relative` with each regular expression of `changes`
# (pairs: expression, replacement) replaced once; an expression that no longer matches
# is an error that says which.
proc ::demo::derived_scene {relative name changes} {
    set source [demo::path $relative]
    set ch [open $source]
    set text [read $ch]
    close $ch
    foreach {expression replacement} $changes {
        if {![regsub -line -- $expression $text $replacement text]} {
            demo::fail "$source no longer contains a line matching '$expression', which the demo\
                changes: update the demo's derived_scene call"
        }
    }
    return [demo::scene_file $name "# Made by the demo [set ::demo::script] from $relative.\n$text"]
}

# True while one of the panes renders.
proc ::demo::rendering {} {
    variable panes
    foreach v $panes {
        if {[winfo exists $v] && [dict get [$v progress] state] eq "running"} { return 1 }
    }
    return 0
}

# The render of v failed: a failure of the demo.
proc ::demo::check_render {v} {
    set p [$v progress]
    if {[dict get $p state] eq "failed"} { demo::fail "the render of [dict get $p file] failed: [dict get $p message]" }
    return $p
}

proc ::demo::run_step {k} {
    variable steps
    variable current $k
    lassign [lindex $steps $k] title text script
    variable caption_title "[expr {$k + 1}]/[llength $steps]  $title"
    variable caption_text $text
    .bar.next configure -state disabled
    update idletasks
    if {[catch {uplevel #0 $script} message]} { demo::fail "$message\n$::errorInfo" }
    after 50 [list demo::when_rendered $k]
}

# Once the step's renders are done: the screenshot, then Next (or, automatically, the next step).
proc ::demo::when_rendered {k} {
    variable current
    variable steps
    variable auto
    variable pause_ms
    variable screenshot
    variable screenshot_step
    if {$k != $current} return
    if {[demo::rendering]} { after 50 [list demo::when_rendered $k]; return }
    variable panes
    foreach v $panes { demo::check_render $v }
    set last [expr {$k == [llength $steps] - 1}]
    set shot_step [expr {$screenshot_step == -1 ? [llength $steps] - 1 : $screenshot_step}]
    if {$screenshot ne "" && $k == $shot_step} { demo::shoot }
    .bar.next configure -state [expr {$last ? "disabled" : "normal"}]
    if {$auto} {
        if {$last && $screenshot ne ""} {
            demo::fail "the demo ended without writing the screenshot $screenshot (a bug of the demo:                its demo::shoot was never reached)"
        }
        if {$last} { after $pause_ms demo::quit } else { after $pause_ms demo::next }
    }
}

# Starts a render of `scene` in v (cleared first, so the tiles appear on black) and shows
# its progress under the pane; `then` is run with the progress dictionary at each update.
proc ::demo::render {v scene {then {}}} {
    $v clear
    demo::note $v "rendering [file tail $scene]"
    $v configure -progresscommand [list demo::show_progress $v [clock milliseconds] $then]
    $v render $scene
}

proc ::demo::show_progress {v started then p} {
    set elapsed [expr {([clock milliseconds] - $started) / 1000.0}]
    switch -- [dict get $p state] {
        running   { demo::note $v [format "rendering %3.0f%%   %.1f s" [expr {100 * [dict get $p fraction]}] $elapsed] }
        done      { demo::note $v [format "rendered in %.2f s" [dict get $p seconds]] }
        cancelled { demo::note $v [format "cancelled at %.0f%%" [expr {100 * [dict get $p fraction]}]] }
        failed    { demo::note $v "render failed" }
    }
    if {$then ne ""} { uplevel #0 [linsert $then end $p] }
}

proc ::demo::next {} {
    variable current
    variable steps
    if {[.bar.next instate disabled] && !$::demo::auto} return
    if {$current + 1 < [llength $steps]} { demo::run_step [expr {$current + 1}] }
}

# Writes a PNG of the whole window as X shows it (ImageMagick's import).
proc ::demo::take_screenshot {file} {
    variable panes
    update
    foreach v $panes { $v redraw }
    update
    if {[auto_execok import] eq ""} {
        demo::fail "VL_DEMO_SCREENSHOT needs ImageMagick's import to write $file (Debian: apt-get install imagemagick)"
    }
    if {[catch {exec import -window [wm frame .] $file} message]} {
        demo::fail "could not write the screenshot $file: $message"
    }
    puts "[set ::demo::script]: wrote $file"
}

proc ::demo::cleanup {} {
    variable temp_dir
    variable panes
    foreach v $panes { if {[winfo exists $v]} { catch {$v cancel} } }
    if {$temp_dir ne ""} { file delete -force $temp_dir }
}

proc ::demo::quit {} {
    demo::cleanup
    exit 0
}

proc ::demo::start {} {
    variable auto
    variable timeout_s
    if {$auto} {
        # A demo that runs by itself must not hang a test: give up after VL_DEMO_TIMEOUT_S.
        if {![string is double -strict $timeout_s] || $timeout_s <= 0} {
            demo::fail "VL_DEMO_TIMEOUT_S is '$timeout_s': give a number of seconds above 0, such as 120"
        }
        after [expr {round(1000 * $timeout_s)}] {
            puts stderr "[set ::demo::script]: step [expr {$::demo::current + 1}] still running after\
                $::demo::timeout_s s with VL_DEMO_AUTOEXIT set: giving up (VL_DEMO_TIMEOUT_S allows more)"
            demo::cleanup
            exit 3
        }
    }
    update
    demo::run_step 0
}

# Shows a pixel's inspect dictionary as the vfb script's status bar does.
proc ::demo::describe {info} {
    if {![dict size $info]} { return "" }
    dict with info {
        set text [format "x %d  y %d  %s  (%.3f %.3f %.3f)" $x $y $srgb $r $g $b]
        if {$tests ne ""} { append text "  tests $tests" }
    }
    return $text
}

# Zooms v to `size` screen pixels per virtual pixel and pans so that the centre of virtual
# pixel (x, y) is in the middle of the window (demo::centre); returns that window point.
proc ::demo::zoom_to {v size x y} {
    $v pixel_size $size
    update idletasks
    set w [winfo width $v]
    set h [winfo height $v]
    $v set_min_x [expr {max(-[$v cget -maxx], $x - $w / $size / 2)}]
    $v set_min_y [expr {max(-[$v cget -maxy], $y - $h / $size / 2)}]
    # Now pixel (x, y)'s centre is at a whole number of pixels from the lower left; pan it
    # to the middle (pan moves the picture right and down by screen pixels).
    set sx [expr {($x - [$v set_min_x]) * $size + $size / 2}]
    set sy [expr {$h - 1 - (($y - [$v set_min_y]) * $size + $size / 2)}]
    $v pan [expr {$w / 2 - $sx}] [expr {$h / 2 - $sy}]
    return [demo::centre $v]
}

# The window point in the middle of v.
proc ::demo::centre {v} { list [expr {[winfo width $v] / 2}] [expr {[winfo height $v] / 2}] }

# Mean and largest tests per pixel of v's last render (every `stride`-th pixel each way).
proc ::demo::test_counts {v {stride 1}} {
    set w [expr {[$v cget -maxx] + 1}]
    set h [expr {[$v cget -maxy] + 1}]
    set size [$v pixel_size]
    set mx [$v set_min_x]
    set my [$v set_min_y]
    $v pixel_size 1
    $v set_min_x 0
    $v set_min_y 0
    set sum 0
    set n 0
    set most 0
    set height [winfo height $v]
    for {set y 0} {$y < $h} {incr y $stride} {
        for {set x 0} {$x < $w} {incr x $stride} {
            # inspect takes window coordinates: at pixel size 1, column x and row height-1-y.
            if {$x >= [winfo width $v] || $y >= $height} continue
            set t [dict get [$v inspect $x [expr {$height - 1 - $y}]] tests]
            if {$t eq ""} continue
            incr sum $t
            incr n
            if {$t > $most} { set most $t }
        }
    }
    $v pixel_size $size
    $v set_min_x $mx
    $v set_min_y $my
    return [list [expr {$n ? double($sum) / $n : 0}] $most]
}
