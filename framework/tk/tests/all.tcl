# Runs the vfb widget's tcltest suite in vfbsh (ctest does, under xvfb-run):
#
#   vfbsh framework/tk/tests/all.tcl ?-outdir DIR? ?-self-check 1? ?tcltest options...?
#
# -outdir is where screenshots go (default: a temporary folder). -self-check 1 enables a
# test that fails on purpose, so that ctest can check that a failure makes this script
# exit 1: tcltest's cleanupTests reports failures but, under wish, still exits 0.
# VFB_UPDATE_EXPECTED=1 in the environment rewrites tests/expected/*.png instead of
# comparing with them (look at them before committing).

set options {}
set ::vfb_test_outdir [file join [expr {[info exists ::env(TMPDIR)] ? $::env(TMPDIR) : "/tmp"}] vfb-test-out-[pid]]
set self_check 0
for {set k 0} {$k < [llength $argv]} {incr k} {
    set a [lindex $argv $k]
    switch -- $a {
        -outdir { set ::vfb_test_outdir [file normalize [lindex $argv [incr k]]] }
        -self-check { set self_check [lindex $argv [incr k]] }
        default { lappend options $a }
    }
}
set ::argv $options  ;# tcltest reads ::argv too: leave it only the options it knows
package require tcltest 2.5
namespace import ::tcltest::*
file mkdir $::vfb_test_outdir [file join $::vfb_test_outdir tmp]
configure -testdir [file dirname [file normalize [info script]]] -tmpdir [file join $::vfb_test_outdir tmp] {*}$options
testConstraint selfCheck $self_check

foreach file [lsort [glob -directory [testsDirectory] *.test]] {
    source $file
}
test self-check-1 {a test that fails on purpose: the suite must exit 1} -constraints selfCheck -body {
    expr {1 + 1}
} -result 3

set failed $::tcltest::numTests(Failed)
set total $::tcltest::numTests(Total)
# cleanupTests prints the summary and resets the counts, and when Tk is loaded it calls
# a bare `exit` (status 0) unless the constraint `interactive` is set: set it, so that the
# exit status below is ours.
testConstraint interactive 1
cleanupTests
if {$total == 0} { puts "all.tcl: no test ran"; exit 1 }
exit [expr {$failed > 0 ? 1 : 0}]
