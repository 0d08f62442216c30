# hsmu_twin.tcl: an OpenSees numerical site for HSMU Console (docs/opensees-twins.md).
#
# OpenSees computes the restoring force of one numerical element of the console's structure
# (its "twin") and receives the console's online model updates as OpenSees parameters
# (`parameter` / `updateParameter`). Run it with the OpenSees interpreter:
#
#     opensees hsmu_twin.tcl                  # port from $HSMU_TWIN_PORT, else 7790
#     HSMU_TWIN_PORT=7791 opensees hsmu_twin.tcl
#
# It listens on 127.0.0.1 (set HSMU_TWIN_BIND=0.0.0.0 for every interface), serves one console
# session and then ends OpenSees. A lab script that builds its own twin model sets
# `set ::hsmuTwinLibrary 1` before sourcing this file, redefines hsmuTwin::build and calls
# `hsmuTwin::serve PORT` itself.
#
# The protocol: text lines (LF) over TCP, numbers as the console prints them (%.17g: every
# double exactly). Requests (console -> OpenSees), each answered by one line unless marked:
#   hello hsmu-twin 1 {ELEMENT}                -> ok hsmu-twin 1 OpenSees VERSION
#   twin LAW NAME VALUE ...                    -> ok twin NAME ...   (builds the model once)
#   param NAME VALUE ...                       (no answer) updateParameter, committed state kept
#   commit                                     (no answer) the last trial is accepted
#   revert                                     (no answer) the last trial is dropped
#   restart                                    (no answer) virgin state, current parameters
#   trial X [N]                                -> ok F X | error TEXT  (N equal sub-steps)
#   bye                                        -> ok bye, then OpenSees ends
# X is the twin's normalized deformation, F its normalized force (the law's x = u / uRef and
# f = F / fRef: the OpenSees material carries the console's normalized parameters 1:1).
# A failed unanswered request (an unknown parameter, say) is reported by the next answer.
#
# Trial / commit: OpenSees' `analyze` commits what it computes, so a trial runs one static step
# to X and is remembered as "ahead"; `commit` logs it. A trial or parameter while ahead (after a
# revert, or a second trial of the same step) first replays the committed history from the
# virgin state (`reset`, the initial parameters, every logged update and step in order): bit for
# bit the committed state, at a cost proportional to the steps so far (a hold is rare).

namespace eval hsmuTwin {
    variable chan ""
    variable log {}          ;# committed events: {p TAG VALUE} or {x VALUE}
    variable ahead 0         ;# OpenSees holds a trial the console has not committed
    variable lastX 0.0
    variable lastN 1
    variable committedX 0.0  ;# X of the last committed step
    variable initial {}      ;# {TAG VALUE ...}: the parameters as built
    variable tags            ;# array: console parameter name -> OpenSees parameter tag
    variable model {}        ;# dict from build: node dof force
    variable pendingError ""
    variable built 0
    variable done 0
    # BoucWen's Newton stops when an update is below this absolute tolerance (the console's law
    # stops below 1e-12 |z|, relative). 1e-15 stays above the one-ulp cycles Newton can end in
    # for |z| up to about 4 (below them OpenSees warns at every step). Measured on the frame of
    # test condition 3, Element 2's force against the built-in run: 1.8e-7 of its peak (1e-12:
    # 1.7e-7; 1e-16: 4.2e-8); docs/opensees-twins.md, Precision.
    variable tolerance 1.0e-15
    variable maxIterations 100
}

# Build the twin model for the console's law and normalized parameters (a dict NAME VALUE).
# Returns a dict: node, dof (where X is imposed), force (a command prefix returning the twin's
# normalized force), params (a dict console-name -> OpenSees parameter tag).
# The default: a zeroLength element with `uniaxialMaterial BoucWen` between a fixed node and a
# node whose displacement is imposed (sp through a Linear time series: the step's time is X).
proc hsmuTwin::build {law values} {
    if {$law ne "boucWen"} {
        error "the OpenSees twin supports the boucWen law only (got $law)"
    }
    foreach name {k0 alpha n beta gamma A0 deltaA deltaNu deltaEta} {
        if {![dict exists $values $name]} { error "twin: $name missing" }
        set p($name) [dict get $values $name]
    }
    wipe
    model BasicBuilder -ndm 1 -ndf 1
    node 1 0.0
    node 2 0.0
    fix 1 1
    # uniaxialMaterial BoucWen tag alpha ko n gamma beta Ao deltaA deltaNu deltaEta tol maxIter
    uniaxialMaterial BoucWen 1 $p(alpha) $p(k0) $p(n) $p(gamma) $p(beta) $p(A0) \
        $p(deltaA) $p(deltaNu) $p(deltaEta) $::hsmuTwin::tolerance $::hsmuTwin::maxIterations
    element zeroLength 1 1 2 -mat 1 -dir 1
    # The console's names -> OpenSees' BoucWen parameter names.
    set osName {k0 ko alpha alpha n n beta beta gamma gamma A0 Ao deltaA deltaA \
                deltaNu deltaNu deltaEta deltaEta}
    set params {}
    set tag 0
    foreach {name os} $osName {
        incr tag
        parameter $tag element 1 material 1 $os
        dict set params $name $tag
    }
    timeSeries Linear 1
    pattern Plain 1 1 { sp 2 1 1.0 }
    constraints Transformation
    numberer Plain
    system UmfPack
    test NormDispIncr 1.0e-12 10 0
    algorithm Linear
    integrator LoadControl 0.0
    analysis Static
    return [dict create node 2 dof 1 force {eleResponse 1 material 1 stress} params $params]
}

# Impose X on the twin and run one static step (commits in OpenSees). Returns analyze's code.
proc hsmuTwin::impose {x} {
    setTime $x
    return [analyze 1]
}

# Go from the committed X to x in n equal static steps (the console's law splits a long
# increment into n = 2^k equal sub-increments; OpenSees integrates each as one step, the same
# backward-Euler map). Returns 0 or analyze's failure code.
proc hsmuTwin::advance {x n} {
    variable committedX
    set xc $committedX
    for {set i 1} {$i <= $n} {incr i} {
        set xi [expr {$i == $n ? $x : $xc + ($x - $xc) * $i / $n}]
        set ok [impose $xi]
        if {$ok != 0} { return $ok }
    }
    return 0
}

proc hsmuTwin::replay {} {
    variable log
    variable initial
    variable ahead
    variable committedX
    reset
    set committedX 0.0
    foreach {tag v} $initial { updateParameter $tag $v }
    foreach ev $log {
        if {[lindex $ev 0] eq "p"} {
            updateParameter [lindex $ev 1] [lindex $ev 2]
        } elseif {[advance [lindex $ev 1] [lindex $ev 2]] != 0} {
            error "replay: the committed step to [lindex $ev 1] failed"
        } else {
            set committedX [lindex $ev 1]
        }
    }
    set ahead 0
}

proc hsmuTwin::answer {text} {
    variable chan
    puts $chan $text
    flush $chan
}

# One request line; returns the answer, or "" for the unanswered requests.
proc hsmuTwin::handle {line} {
    variable log
    variable ahead
    variable lastX
    variable lastN
    variable committedX
    variable initial
    variable tags
    variable model
    variable pendingError
    variable built
    variable done
    set cmd [lindex $line 0]
    set args [lrange $line 1 end]
    switch -- $cmd {
        hello {
            puts "hsmu-twin: the console's element [lindex $args 2]"
            flush stdout
            return "ok hsmu-twin 1 OpenSees [version]"
        }
        twin {
            if {$built} { return "error twin: the model is built already" }
            set law [lindex $args 0]
            set values [lrange $args 1 end]
            if {[llength $values] % 2 != 0} { return "error twin: NAME VALUE pairs expected" }
            set model [build $law $values]
            dict for {name tag} [dict get $model params] {
                set tags($name) $tag
                lappend initial $tag [dict get $values $name]
            }
            set built 1
            return "ok twin [lsort [array names tags]]"
        }
        param {
            if {!$built} { set pendingError "param before twin"; return "" }
            if {$ahead} { replay }
            foreach {name v} $args {
                if {![info exists tags($name)]} {
                    set pendingError "param: the twin has no parameter $name"
                    continue
                }
                updateParameter $tags($name) $v
                lappend log [list p $tags($name) $v]
            }
            return ""
        }
        commit {
            if {$ahead == 1} {
                lappend log [list x $lastX $lastN]
                set committedX $lastX
                set ahead 0
            }
            return ""
        }
        revert {
            # The trial stays in OpenSees until something needs the committed state.
            if {$ahead} { set ahead 2 }
            return ""
        }
        restart {
            # Back to the virgin state with the current parameters (the console's revertToStart).
            if {!$built} { return "" }
            reset
            set log {}
            set committedX 0.0
            set current {}
            foreach {tag v} $initial { lappend current $tag [getParamValue $tag] }
            set initial $current
            set ahead 0
            return ""
        }
        trial {
            if {!$built} { return "error trial before twin" }
            if {$pendingError ne ""} {
                set why $pendingError
                set pendingError ""
                return "error $why"
            }
            if {$ahead} { replay }
            set x [lindex $args 0]
            set n [expr {[llength $args] > 1 ? [lindex $args 1] : 1}]
            if {![string is double -strict $x] || ![string is integer -strict $n] || $n < 1} {
                return "error trial: X and an optional sub-step count >= 1 expected"
            }
            set lastX $x
            set lastN $n
            set ahead 1
            if {[advance $x $n] != 0} { return "error OpenSees: the step to $x failed" }
            set f [eval [dict get $model force]]
            set d [nodeDisp [dict get $model node] [dict get $model dof]]
            return [format "ok %.17g %.17g" $f $d]
        }
        bye {
            set done 1
            return "ok bye"
        }
        default {
            return "error unknown request '$cmd'"
        }
    }
}

proc hsmuTwin::accept {sock addr port} {
    variable chan
    if {$chan ne ""} { close $sock; return }
    fconfigure $sock -translation lf -buffering line -blocking 1
    set chan $sock
}

proc hsmuTwin::serve {port {bind ""}} {
    variable chan
    variable done
    if {$bind eq ""} {
        set bind 127.0.0.1
        if {[info exists ::env(HSMU_TWIN_BIND)] && $::env(HSMU_TWIN_BIND) ne ""} {
            set bind $::env(HSMU_TWIN_BIND)
        }
    }
    set server [socket -server hsmuTwin::accept -myaddr $bind $port]
    puts "hsmu-twin: listening on $bind:$port"
    flush stdout
    vwait hsmuTwin::chan
    close $server
    while {!$done && [gets $chan line] >= 0} {
        if {[string trim $line] eq ""} { continue }
        if {[catch {handle $line} reply]} {
            set reply [string map {"\n" " "} $reply]
            if {[lindex $line 0] in {param commit revert restart}} {
                set hsmuTwin::pendingError $reply
                set reply ""
            } else {
                set reply "error $reply"
            }
        }
        if {$reply ne ""} { answer $reply }
    }
    close $chan
    puts "hsmu-twin: session ended"
}

if {![info exists ::hsmuTwinLibrary]} {
    set hsmuTwinPort 7790
    if {[info exists ::env(HSMU_TWIN_PORT)] && $::env(HSMU_TWIN_PORT) ne ""} {
        set hsmuTwinPort $::env(HSMU_TWIN_PORT)
    }
    hsmuTwin::serve $hsmuTwinPort
    wipe
    exit
}
