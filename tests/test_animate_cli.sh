# tippe animate: films read back by ffprobe (codec, size, frame count = duration x fps),
# a still picture, and bad usage that costs nothing and leaves nothing.
source "$(dirname "$0")/lib.sh"
setup "$@"
command -v ffprobe >/dev/null || skip "ffprobe not installed (apt-get install ffmpeg)"

flip=designs/scenarios/film-IIb-flip.json
small=(--size 160x120 --fps 10)

# probe FILE: "codec width height frames duration" of the first video stream.
probe() {
    ffprobe -v error -count_frames -select_streams v:0 \
        -show_entries stream=codec_name,width,height,nb_read_frames:format=duration \
        -of default=noprint_wrappers=1:nokey=0 "$1" |
        awk -F= '{v[$1]=$2} END {print v["codec_name"], v["width"], v["height"], v["nb_read_frames"], v["duration"]}'
}

# film EXT CODEC: a 2 s film at 10 fps has 20 frames and lasts 2 s.
film() {
    local ext=$1 codec=$2 out="$tmp/flip.$1"
    if ! "$tippe" animate "$flip" -o "$out" "${small[@]}" --length 2 --json >"$tmp/film.json" 2>"$tmp/err"; then
        bad "$ext: tippe animate failed: $(cat "$tmp/err")"
        return
    fi
    read -r c w h n d <<<"$(probe "$out")"
    # duration x fps = frames; GIF delays are whole centiseconds, so 2 s within 0.05 s
    check "$ext: codec $c, size ${w}x$h, $n frames, $d s (want $codec 160x120, 20 frames, 2 s)" \
        awk -v c="$c" -v w="$w" -v h="$h" -v n="$n" -v d="$d" -v want="$codec" \
        'BEGIN { exit !(c == want && w == 160 && h == 120 && n == 20 && d > 1.95 && d < 2.05) }'
    check "$ext: JSON summary matches the file" json_ok "$tmp/film.json" \
        "o['frames'] == 20 and o['fps'] == 10 and o['bytes'] == $(stat -c %s "$out") and o['verdict'] in ('tip', 'undecided')"
}
film mp4 h264
film webm vp9
film gif gif

# The default film: the whole launch, to a tenth past the later of its proof and the time
# theta comes within 0.05 rad of the end state for good, in 10 s.
check "default film" "$tippe" animate "$flip" -o "$tmp/default.mp4" --size 64x64 --json >"$tmp/d.json"
check "default: 300 frames to 1.1 x max(t_verdict, t_settled)" json_ok "$tmp/d.json" \
    "o['frames'] == 300 and o['film_s'] == 10 and o['verdict'] == 'tip' and o['t_settled_s'] >= o['t_verdict_s'] and abs(o['t_shown_s'] - 1.1 * o['t_settled_s']) < 1e-9 * o['t_shown_s'] and abs(o['theta_final_rad'] - math.pi) < 1e-9"

# --speed: model seconds per film second; t_end 3 s at speed 1.5 and 10 fps is 21 frames.
check "speed" "$tippe" animate "$flip" --t-end 3 --speed 1.5 -o "$tmp/s.mp4" "${small[@]}" --json >"$tmp/s.json"
check "speed: 21 frames" json_ok "$tmp/s.json" "o['frames'] == 21 and abs(o['speed'] - 1.5) < 1e-12"

# To a pipe (no seeking back): a fragmented MP4, still 10 frames; the summary goes to stderr.
"$tippe" animate "$flip" -o - --format mp4 "${small[@]}" --length 1 2>"$tmp/pipe.err" | cat >"$tmp/pipe.mp4"
read -r c w h n _ <<<"$(probe "$tmp/pipe.mp4")"
check "pipe: $c ${w}x$h, $n frames (want h264 160x120, 10 frames)" test "$c $w $h $n" = "h264 160 120 10"
check "pipe: summary on stderr" grep -q "^film" "$tmp/pipe.err"

# A lift-off ends the film: the model has no state beyond it (docs/dynamics.md's example).
# The planning and the sampled run take different steps and locate the lift-off apart by
# about their tolerance (rtol 1e-9): 1e-6 relative.
check "lift-off film" "$tippe" animate designs/scenarios/fig12-hang.json --spin 100 --theta 0.3 \
    -o "$tmp/lift.mp4" --size 64x64 --fps 5 --length 1 --json >"$tmp/lift.json"
check "lift-off: the film ends at the lift-off" json_ok "$tmp/lift.json" \
    "o['verdict'] == 'lost_contact' and abs(o['t_shown_s'] - o['t_verdict_s']) < 1e-6 * o['t_verdict_s']"

# One picture.
check "still" "$tippe" animate "$flip" --frame 5 -o "$tmp/still.png" "${small[@]}" >/dev/null
read -r c w h _ <<<"$(probe "$tmp/still.png")"
check "still: PNG 160x120 (got $c ${w}x$h)" test "$c $w $h" = "png 160 120"

# A design's hand launch (as tippe check).
check "design" "$tippe" animate designs/m12-setscrew.json --z2 10 --spin 60 --t-end 20 \
    -o "$tmp/m12.gif" "${small[@]}" --length 1 >/dev/null
expect_fail "design without --z2" 2 "--z2" -- animate designs/m12-setscrew.json -o "$tmp/x.mp4"

# Bad usage: exit 2, a message, nothing on disk.
expect_fail "no output" 2 "-o" -- animate "$flip"
expect_fail "unknown format" 2 "x.avi" ".mp4" -- animate "$flip" -o "$tmp/x.avi"
expect_fail "png without --frame" 2 "--frame" -- animate "$flip" -o "$tmp/x.png"
expect_fail "--frame to a film" 2 ".png" -- animate "$flip" --frame 1 -o "$tmp/x.mp4"
expect_fail "odd size" 2 "--size" "even" -- animate "$flip" -o "$tmp/x.mp4" --size 161x120
expect_fail "huge size" 2 "--size" -- animate "$flip" -o "$tmp/x.mp4" --size 10000x10000
expect_fail "fps 0" 2 "--fps" "120" -- animate "$flip" -o "$tmp/x.mp4" --fps 0
expect_fail "negative speed" 2 "--speed" -- animate "$flip" -o "$tmp/x.mp4" --speed -1
expect_fail "too slow a film" 2 "frames" "at most 36000" -- animate "$flip" -o "$tmp/x.mp4" --speed 1e-4
expect_fail "frame past t_end" 2 "t_end" -- animate "$flip" --frame 1000 -o "$tmp/x.png"
expect_fail "unwritable directory" 2 "-o" "$tmp/none/x.mp4" -- animate "$flip" -o "$tmp/none/x.mp4"
expect_fail "bad scenario" 2 "mu" -- animate "$flip" --mu -1 -o "$tmp/x.mp4"
check "bad usage left nothing behind" test -z "$(ls "$tmp" | grep -E '^x\.|\.tmp\.')"

# A user's old file survives a failed run.
echo "old film" >"$tmp/keep.mp4"
"$tippe" animate "$flip" --mu -1 -o "$tmp/keep.mp4" >/dev/null 2>&1
check "old file kept after a failure" grep -q "old film" "$tmp/keep.mp4"

# issue 28.8: a frame after t_end is refused before the launch is integrated, naming --frame
expect_fail "--frame after t_end" 2 "--frame 1e+06 s" "0 .. t_end = 600 s" -- \
    animate designs/m12-setscrew.json --z2 12 --frame 1e6 -o "$tmp/late.png"
check "--frame after t_end: no picture" test ! -e "$tmp/late.png"

# A Z2 where the screw stands out of the ball (beyond sqrt(25^2 - 5.5^2) - 7.5 =
# 16.887 mm): the film's report says the model does not apply, as check does.
"$tippe" animate designs/m12-setscrew.json --z2 18 --frame 0.1 -o "$tmp/out18.png" >"$tmp/o18.txt"
check "a protruding screw: the report says contact INVALID" grep -q "^contact   INVALID at Z2 = 18 mm" "$tmp/o18.txt"
"$tippe" animate designs/m12-setscrew.json --z2 18 --frame 0.1 -o "$tmp/out18.png" --json >"$tmp/o18.json"
check "a protruding screw: JSON model_valid false, 1.086 mm out" python3 -c '
import json, math, sys
o = json.load(open(sys.argv[1]))
assert o["model_valid"] is False, o["model_valid"]
assert abs(o["protrusion"]["protrusion_mm"] - (math.hypot(5.5, 25.5) - 25)) < 1e-5, o["protrusion"]' "$tmp/o18.json"

finish
