#!/usr/bin/env bash
# The viewer's tests, one CTest test per case (tools/viewer/CMakeLists.txt):
#
#   viewer_test.sh CASE BIN_DIR WORK_DIR
#
#   probes  the probes: the generated skeletons count as unfinished, the solutions (built as
#           the student's code) as finished, and a student with only milestone 1 gets their
#           own lines and the reference for the rest (likewise milestones 1-2 and 1-4)
#   xvfb    scripted run under Xvfb (xvfb-run -a): real SDL events; the screenshots change as
#           the model turns, is dragged, panned, zoomed and relit; the wireframe is lines;
#           milestone 5's modes (keys 7 to 9) draw, and the circling light (O) moves the shadow
#   dummy   the same without any X server (SDL_VIDEODRIVER=dummy)
#   robust  bad OBJ files and extreme cameras: a message, a picture, exit code 0
#   gif     --gif writes the light circling the shadowed scene: the frames asked for, a shadow
#           that moves; the GIF committed for lesson 5 is small (<= 200x200, <= 40 frames)
#
# BIN_DIR holds viewer, viewer_solved, viewer_skeleton, viewer_m1_only, viewer_m1_m2,
# viewer_m1_m4 and viewer_shots (which measures the screenshots: see shots.cpp). Exits 77
# (CTest: skipped) when xvfb-run is missing.
set -euo pipefail
case_name=$1 bin=$(cd "$2" && pwd) work=$3
src=$(cd "$(dirname "$0")/../.." && pwd)
rm -rf "$work"
mkdir -p "$work"
cd "$work"

fail() {
    echo "FAIL: $*" >&2
    exit 1
}
# field FILE NAME: a number viewer_shots prints for FILE ("drawn", "thin")
field() { "$bin/viewer_shots" "$1" | awk -v k="$2" '{ for (i = 1; i < NF; ++i) if ($i == k) print $(i + 1) }'; }
differ() { "$bin/viewer_shots" "$1" "$2" | awk '$1 == "differ" { print $2 }'; }
expect_size() {
    [ -f "$1" ] || fail "no screenshot $1"
    read -r _ w h _ < <("$bin/viewer_shots" "$1")
    [ "$w" = 800 ] && [ "$h" = 600 ] || fail "$1 is ${w}x$h, not 800x600"
}
expect_differ() {  # A B MIN WHAT
    local d
    d=$(differ "$1" "$2")
    echo "$4: $d pixels differ"
    [ "$d" -ge "$3" ] || fail "$4: only $d pixels differ between $1 and $2 (at least $3 expected)"
}
run_viewer() {  # LOG PROGRAM ARGS...: runs it, fails on a crash or a non-zero exit
    local log=$1
    shift
    if ! timeout 60 "$@" >"$log" 2>&1; then
        cat "$log"
        fail "exited with an error: $*"
    fi
}

case "$case_name" in
probes)
    out=$("$bin/viewer_skeleton" --probe)
    echo "$out"
    [ "$(grep -c ': reference (' <<<"$out")" -eq 5 ] || fail "the skeletons must count as unfinished"
    grep -q '^m5 textures: reference (your code: draws nothing yet)' <<<"$out" ||
        fail "milestone 5's skeleton must count as drawing nothing yet"
    out=$("$bin/viewer_solved" --probe)
    echo "$out"
    [ "$(grep -c ': yours (' <<<"$out")" -eq 5 ] || fail "the solutions must count as finished"
    grep -q '^m5 textures: yours' <<<"$out" || fail "milestone 5 solved must count as finished"
    out=$("$bin/viewer_m1_only" --probe)
    echo "$out"
    grep -q '^m1 lines: yours' <<<"$out" || fail "milestone 1 solved must count as finished"
    [ "$(grep -c ': reference (' <<<"$out")" -eq 4 ] || fail "milestones 2 to 5 are skeletons there"
    out=$("$bin/viewer_m1_m2" --probe)
    echo "$out"
    [ "$(grep -c ': yours (' <<<"$out")" -eq 2 ] && grep -q '^m2 triangles: yours' <<<"$out" ||
        fail "milestones 1 and 2 solved must count as finished, and only they"
    out=$("$bin/viewer_m1_m4" --probe)
    echo "$out"
    [ "$(grep -c ': yours (' <<<"$out")" -eq 4 ] && grep -q '^m5 textures: reference' <<<"$out" ||
        fail "milestones 1 to 4 solved must count as finished, milestone 5's skeleton not"
    ;;

xvfb | dummy)
    if [ "$case_name" = xvfb ]; then
        command -v xvfb-run >/dev/null || { echo "xvfb-run is not installed (Debian: xvfb): skipped"; exit 77; }
        launch=(xvfb-run -a -s "-screen 0 1024x768x24")
    else
        launch=(env SDL_VIDEODRIVER=dummy)
    fi
    script="key 2; screenshot flat.png; key Left 5; screenshot flat_turned.png
            key 1; screenshot wire.png
            key 3; screenshot gouraud.png; drag left 400 300 480 330; screenshot dragged.png
            drag right 400 300 300 300; screenshot panned.png; wheel 3; screenshot zoomed.png
            key 4; screenshot perpixel.png; key i 6; key j 4; screenshot relit.png
            key 5; screenshot depth.png; key 6; screenshot normals.png
            key r; key 7; screenshot textured.png; key 8; screenshot specular.png; key 9; screenshot shadowed.png
            key o; frames 30; key o; screenshot circled.png; quit"
    run_viewer solved.log "${launch[@]}" "$bin/viewer_solved" --no-help --events "$script"
    cat solved.log
    for f in flat flat_turned wire gouraud dragged panned zoomed perpixel relit depth normals textured specular \
        shadowed circled; do expect_size $f.png; done
    grep -q 'wireframe: drawn by your m1 lines, your m3 transforms' solved.log || fail "the solutions' wireframe is not theirs"
    grep -q 'Gouraud: drawn by your m4 draw_mesh' solved.log || fail "the solutions' Gouraud is not theirs"
    for m in textured specular shadowed; do
        grep -q "$m: drawn by your m5 draw_scene" solved.log || fail "the solutions' $m mode is not theirs"
        n=$(field $m.png drawn)
        echo "$m: $n drawn"
        [ "$n" -ge 20000 ] || fail "the $m mode covers only $n pixels"
    done

    flat=$(field flat.png drawn) flat_thin=$(field flat.png thin)
    wire=$(field wire.png drawn) wire_thin=$(field wire.png thin)
    echo "flat: $flat drawn, $flat_thin thin; wireframe: $wire drawn, $wire_thin thin"
    [ "$flat" -ge 20000 ] || fail "the flat model covers only $flat pixels"
    [ "$wire" -ge 2000 ] || fail "the wireframe has only $wire line pixels"
    [ "$wire" -lt $((flat / 2)) ] || fail "the wireframe ($wire) is not sparser than the flat model ($flat)"
    [ $((wire_thin * 10)) -ge $((wire * 7)) ] || fail "the wireframe's pixels are not lines ($wire_thin of $wire thin)"
    [ $((flat_thin * 10)) -le "$flat" ] || fail "the flat model is not solid ($flat_thin of $flat thin)"
    expect_differ flat.png flat_turned.png 2000 "rotation (Left arrow)"
    expect_differ gouraud.png dragged.png 2000 "orbit (left drag)"
    expect_differ dragged.png panned.png 2000 "pan (right drag)"
    zoomed=$(field zoomed.png drawn) panned=$(field panned.png drawn)
    [ "$zoomed" -gt $((panned * 11 / 10)) ] || fail "zooming in (wheel) did not enlarge the model ($panned -> $zoomed)"
    expect_differ perpixel.png relit.png 2000 "light moved (I, J)"
    expect_differ perpixel.png depth.png 2000 "depth view"
    expect_differ depth.png normals.png 2000 "normals view"
    expect_differ normals.png textured.png 2000 "textured mode"
    expect_differ textured.png specular.png 2000 "specular mode"
    expect_differ specular.png shadowed.png 2000 "shadowed mode (the floor)"
    [ "$(field shadowed.png drawn)" -gt "$(field specular.png drawn)" ] || fail "the shadowed mode shows no floor"
    expect_differ shadowed.png circled.png 1000 "the light circling (O): shading and shadow move"

    if [ "$case_name" = xvfb ]; then
        # A student with only milestone 1: the wireframe is theirs (lines) on the reference's
        # transforms, and looks like the reference's.
        run_viewer m1.log "${launch[@]}" "$bin/viewer_m1_only" --no-help --events "key 1; screenshot wire_m1.png"
        run_viewer ref.log "${launch[@]}" "$bin/viewer_skeleton" --no-help \
            --events "key 1; screenshot wire_ref.png; key 2; screenshot flat_ref.png; key 9; screenshot shadowed_ref.png"
        grep -q 'wireframe: drawn by your m1 lines, reference m3 transforms' m1.log || fail "m1 alone: the lines are not the student's"
        grep -q 'wireframe: drawn by reference m1 lines, reference m3 transforms' ref.log || fail "skeleton: not the reference"
        grep -q 'shadowed: drawn by reference m5 draw_scene' ref.log || fail "skeleton: milestone 5 is not the reference's"
        [ "$(field shadowed_ref.png drawn)" -ge 20000 ] || fail "skeleton: the reference's shadowed mode draws nothing"
        # Milestones 1 to 4 done, 5 not yet: their draw_mesh, the reference's draw_scene.
        run_viewer m14.log "${launch[@]}" "$bin/viewer_m1_m4" --no-help --events "key 4; frames 1; key 7; frames 1"
        grep -q 'per-pixel: drawn by your m4 draw_mesh' m14.log && grep -q 'textured: drawn by reference m5 draw_scene' m14.log ||
            { cat m14.log; fail "m1 to m4: per-pixel must be theirs, textured the reference's"; }
        d=$(differ wire_m1.png wire_ref.png)
        echo "m1 alone against the reference: $d pixels differ"
        [ "$d" -le 50 ] || fail "the wireframe of m1 alone differs from the reference's in $d pixels"
        # Milestones 1 and 2: flat is the student's triangles in the painter's order (no depth
        # buffer yet), close to the reference's depth-tested picture.
        run_viewer m12.log "${launch[@]}" "$bin/viewer_m1_m2" --no-help --events "key 2; screenshot flat_m12.png"
        grep -q "flat: drawn by your m2 triangles in reference m3 painter's order" m12.log ||
            fail "m1 and m2: flat is not drawn by the student's triangles"
        d=$(differ flat_m12.png flat_ref.png) flat=$(field flat_ref.png drawn)
        echo "m1 and m2, flat, against the reference: $d of $flat pixels differ"
        [ $((d * 50)) -le "$flat" ] || fail "m1 and m2: flat differs from the reference's in $d of $flat pixels"
    else
        # The student's own viewer (whatever stage their code is at) starts and draws.
        run_viewer student.log "${launch[@]}" "$bin/viewer" --no-help --events "frames 2; screenshot student.png"
        cat student.log
        [ "$(field student.png drawn)" -ge 20000 ] || fail "the student's viewer draws nothing"
    fi
    ;;

robust)
    launch=(env SDL_VIDEODRIVER=dummy)
    printf 'v 0 0 0\nv 1 0\nf 1 2 3\n' >short_vertex.obj
    printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n' >bad_index.obj
    printf 'v 1 1 1\nv 1 1 1\nv 1 1 1\nf 1 2 3\n' >no_size.obj
    printf 'v -1e308 0 0\nv 1e308 0 0\nv 0 1e308 0\nf 1 2 3\n' >huge.obj
    head -c 20000 /dev/urandom >garbage.obj
    mkdir -p a_directory.obj
    for f in short_vertex bad_index no_size huge garbage a_directory missing; do
        run_viewer "$f.log" "${launch[@]}" "$bin/viewer_solved" "$f.obj" --no-help --events "screenshot $f.png"
        if [ "$f" = huge ]; then  # loads: coordinates of 1e308 are scaled without overflow
            grep -q 'cannot' "$f.log" && { cat "$f.log"; fail "huge.obj should load"; }
        else
            grep -q 'viewer: cannot' "$f.log" || { cat "$f.log"; fail "$f.obj: no message"; }
        fi
        [ "$(field "$f.png" drawn)" -ge 1000 ] || fail "$f.obj: nothing on screen"
        echo "$f.obj: $(grep -m1 'viewer: cannot' "$f.log" || echo loaded)"
    done
    script="key w 80; screenshot inside.png; key r; key s 250; screenshot far.png
            key r; drag right 400 300 2400 300; screenshot off.png; key r; key Left 31; screenshot behind.png
            key Up 40; key Down 80; wheel -2000; wheel 4000; key a 500; key e 500; drag right 0 0 30000 30000
            key 1; key w 200; key 2; key s 400; key 3; key 4; key 5; key 6; key 7; key 8; key 9; key o; frames 2
            key r; key w 60; key 9; frames 2; key s 300; key 7; frames 2; key i 30; key 9; frames 2; key k 60; frames 2
            screenshot end.png"
    for program in viewer_solved viewer_skeleton; do
        run_viewer "$program.log" "${launch[@]}" "$bin/$program" --no-help --events "$script"
        cat "$program.log"
        grep -q 'inside the model' "$program.log" || fail "$program: no message inside the model"
        grep -q 'far away' "$program.log" || fail "$program: no message far away"
        grep -q 'nothing in view' "$program.log" || fail "$program: no message with the model off screen"
        [ "$(field behind.png drawn)" -ge 20000 ] || fail "$program: the model seen from behind is missing"
    done
    ;;

gif)
    run_viewer gif.log "$bin/viewer_solved" torus --mode shadowed --size 120x120 --gif light.gif 12
    cat gif.log
    grep -q 'shadowed, drawn by your m5 draw_scene' gif.log || fail "the GIF is not drawn by the solutions' draw_scene"
    read -r _ w h _ frames _ delay _ moving _ drawn < <("$bin/viewer_shots" --gif light.gif)
    echo "light.gif: ${w}x$h, $frames frames, $delay cs each, $moving pixels move by half a turn, $drawn drawn"
    [ "$w" = 120 ] && [ "$h" = 120 ] && [ "$frames" = 12 ] || fail "light.gif is ${w}x$h with $frames frames (120x120, 12 asked)"
    [ "$drawn" -ge 5000 ] || fail "light.gif draws only $drawn pixels"
    [ "$moving" -ge 300 ] || fail "the light circles but only $moving pixels change"
    # The reference draws the same frames for a skeleton.
    run_viewer gif_ref.log "$bin/viewer_skeleton" torus --mode shadowed --size 120x120 --gif light_ref.gif 12
    grep -q 'shadowed, drawn by reference m5 draw_scene' gif_ref.log || fail "a skeleton's GIF is not the reference's"
    # Bad requests: a usage message, no file.
    for bad in "--gif" "--gif x.gif 1" "--gif x.gif 401"; do
        # shellcheck disable=SC2086
        if "$bin/viewer_solved" $bad >bad.log 2>&1; then fail "viewer $bad was accepted"; fi
        [ ! -e x.gif ] || fail "viewer $bad wrote a file"
    done
    # Lesson 5's GIF, as `make viewer-screenshots` writes it: small enough for a web page.
    committed=$src/milestone5_textures_shadows/light_circle.gif
    [ -f "$committed" ] || fail "$committed is missing (make viewer-screenshots writes it)"
    read -r _ w h _ frames _ _ _ moving _ drawn < <("$bin/viewer_shots" --gif "$committed")
    bytes=$(wc -c <"$committed")
    echo "$committed: ${w}x$h, $frames frames, $bytes bytes, $moving pixels move"
    [ "$w" -le 200 ] && [ "$h" -le 200 ] && [ "$frames" -le 40 ] || fail "the lesson's GIF is larger than 200x200 or 40 frames"
    [ "$moving" -ge 300 ] && [ "$drawn" -ge 5000 ] || fail "the lesson's GIF does not show the shadow moving"
    ;;

*)
    echo "unknown case $case_name" >&2
    exit 2
    ;;
esac
echo "PASS: $case_name"
