#!/usr/bin/env bash
# A pile with collisions falls asleep, and the view shows it: the status bar counts collisions,
# resting contacts and sleeping particles; the Sleep toggle tints the sleeping balls slate grey
# (their pixels lose their palette colour) and the Contacts toggle draws the loaded contacts as
# amber-to-white lines through the pile. Both toggles are off by default. Particle 0 launched
# again (L) falls on the pile and wakes part of it, which falls asleep again.
# Two runs of the same deterministic scene, each screenshot taken asleep when the app quits:
# Sleep only, then Sleep and Contacts; the contacts are what differs between them.
# Usage: pile_view.sh <particle-lab binary> <source dir>   (PILE_VIEW_KEEP=DIR keeps the screenshots)
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir
STATE="$WORK/state.json"
COUNT=300

# 300 balls of 2 cm in a 0.4 m x 0.4 m room: a pile four layers deep, asleep within ~3 s.
cat >"$WORK/pile.json" <<EOF
{"format": "particle-lab-preset", "version": 1, "name": "pile view test",
 "room": {"center": [0, 0.5, 0], "size": [0.4, 1, 0.4]}, "world": {"gravity": [0, -9.81, 0]},
 "drag": {"model": "none"}, "contact": {"restitution": 0.5, "friction": 0.5, "rest_speed": 0.05},
 "collisions": {"enabled": true, "restitution": 0.5, "friction": 0.5},
 "integrator": {"method": "semi_implicit_euler", "dt": 0.002},
 "emitter": {"count": $COUNT, "seed": 1, "region_min": [-0.18, 0.05, -0.18], "region_max": [0.18, 0.5, 0.18],
             "speed_min": 0, "speed_max": 0.5, "direction": [0, 1, 0], "spread_deg": 90,
             "mass_min": 0.03, "mass_max": 0.03, "radius_min": 0.02, "radius_max": 0.02}}
EOF

# Clicks a toolbar toggle until the state dump shows it on. The button is held across a frame:
# a slow frame (software GL under load) misses a click whose press and release fall inside it.
toggle_on() {
    local widget=$1 key=$2 x y
    for _ in $(seq 5); do
        read -r x y < <(widget_center "$STATE" "$widget")
        xdotool mousemove --window "$APP_WINDOW" "$x" "$y" mousedown 1
        sleep 0.3
        xdotool mouseup 1
        for _ in $(seq 20); do
            dump_now "$STATE"
            json_get "$STATE" "d['view']['$key']" | grep -q True && return 0
            sleep 0.1
        done
    done
    fail "clicking $widget did not turn it on"
}

ALL_ASLEEP="all(v['asleep_count'] == v['particle_count'] for v in d['variants'])"

# Polls (up to 120 s: the physics runs slower than real time on a loaded machine) until
# CONDITION holds in the state dump.
wait_long() {
    local condition=$1 message=$2
    for _ in $(seq 240); do
        dump_now "$STATE"
        "$PYTHON" -c 'import json, sys; d = json.load(open(sys.argv[1])); sys.exit(0 if eval(sys.argv[2]) else 1)' \
            "$STATE" "$condition" && return 0
        sleep 0.5
    done
    fail "$message (condition: $condition; status: $(json_get "$STATE" 'd["collision_status"]'))"
}

# The screen rectangle (pixels "x0 y0 x1 y1") around the centre of the pile's balls as the
# last dump saw them: the middle half of their extent, where the view shows only balls.
pile_rect() {
    json_get "$STATE" "(lambda s: ' '.join(str(round(v)) for v in (
        (3 * min(s[0]) + max(s[0])) / 4, (3 * min(s[1]) + max(s[1])) / 4,
        (min(s[0]) + 3 * max(s[0])) / 4, (min(s[1]) + 3 * max(s[1])) / 4)))(
        list(zip(*[p['screen'] for p in d['variants'][0]['particles'] if p['screen']])))"
}

# Counts the pixels of a PNG inside "x0 y0 x1 y1": all, vivid (saturation > 0.45: a palette
# colour), slate (saturation < 0.3, blue at least red - 12: the sleeping tint) and amber (red over
# blue by more than 30: a contact line over the slate balls).
pixel_classes() {
    if [ ! -x "$WORK/pixel_classes" ]; then
        cc -O2 -std=c11 -I/usr/include/stb -o "$WORK/pixel_classes" -x c - -lstb -lm <<'C' || fail "cannot build the pixel counter"
#include <stdio.h>
#include <stdlib.h>
#include <stb_image.h>
int main(int argc, char** argv) {
    int w, h, n;
    unsigned char* px = stbi_load(argv[1], &w, &h, &n, 3);
    if (!px || argc < 6) return 1;
    int x0 = atoi(argv[2]), y0 = atoi(argv[3]), x1 = atoi(argv[4]), y1 = atoi(argv[5]);
    long all = 0, vivid = 0, slate = 0, amber = 0;
    for (int y = y0 < 0 ? 0 : y0; y < y1 && y < h; ++y)
        for (int x = x0 < 0 ? 0 : x0; x < x1 && x < w; ++x) {
            const unsigned char* p = px + 3 * ((long)y * w + x);
            int r = p[0], g = p[1], b = p[2];
            int hi = r > g ? (r > b ? r : b) : (g > b ? g : b), lo = r < g ? (r < b ? r : b) : (g < b ? g : b);
            double sat = hi > 0 ? (double)(hi - lo) / hi : 0.0;
            ++all;
            if (sat > 0.45 && hi > 60) ++vivid;
            if (sat < 0.3 && hi > 60 && b >= r - 12) ++slate;
            if (r - b > 30 && hi > 60) ++amber;
        }
    printf("%ld %ld %ld %ld\n", all, vivid, slate, amber);
    return 0;
}
C
    fi
    "$WORK/pixel_classes" "$@"
}

# One run: the toggles named in $@ on, asleep, then quit with a screenshot ($WORK/$shot.png);
# writes the pixel classes of the pile's middle to $WORK/$shot.counts.
run_pile() {
    local shot=$1
    shift
    start_app "$WORK/pile.json" --frames 1000000 --dump-state "$STATE" --screenshot "$WORK/$shot.png"
    wait_for_state "$STATE" '"view.contacts" in d["widgets"] and "view.sleep" in d["widgets"]' \
        "there are no Contacts and Sleep toggles in the view toolbar"
    json_check "$STATE" 'not d["view"]["contacts"] and not d["view"]["tint_sleeping"]' "Contacts or Sleep is on by default"
    for toggle in "$@"; do toggle_on "view.$toggle" "$([ "$toggle" = sleep ] && echo tint_sleeping || echo contacts)"; done
    wait_long "$ALL_ASLEEP" "the pile did not fall asleep"
    [ "$shot" = both ] && wake_and_sleep_again
    local rect
    rect=$(pile_rect)
    echo "pile middle on screen: $rect"
    quit_app
    [ -s "$WORK/$shot.png" ] || fail "no screenshot written at quit"
    # shellcheck disable=SC2086
    pixel_classes "$WORK/$shot.png" $rect >"$WORK/$shot.counts"
    if [ -n "${PILE_VIEW_KEEP:-}" ]; then cp "$WORK/$shot.png" "$PILE_VIEW_KEEP/"; fi
}

# The status bar while asleep; then L: particle 0 falls back onto the pile and wakes part of it.
wake_and_sleep_again() {
    local status
    status=$(json_get "$STATE" 'd["collision_status"]')
    echo "asleep: $status"
    [[ "$status" =~ ^([0-9]+)\ collisions\ \(0\ in\ the\ last\ step\)\ ·\ ([0-9]+)\ resting\ contacts\ ·\ ([0-9]+)\ asleep$ ]] ||
        fail "the status bar's collision counters read \"$status\""
    [ "${BASH_REMATCH[1]}" -gt 0 ] || fail "no collisions counted while a pile formed"
    [ "${BASH_REMATCH[3]}" -eq "$COUNT" ] || fail "the status bar says ${BASH_REMATCH[3]} asleep, not $COUNT"
    # Every ball of a pile at rest carries its weight on at least one loaded contact below it.
    [ "${BASH_REMATCH[2]}" -ge "$COUNT" ] || fail "only ${BASH_REMATCH[2]} resting contacts under $COUNT sleeping balls"
    press l
    # Particle 0 itself wakes at its launch; the pile wakes where it lands.
    wait_long "d['variants'][0]['asleep_count'] < $COUNT - 1" "particle 0 fell on the pile and woke none of it"
    echo "woken: $(json_get "$STATE" 'd["collision_status"]')"
    wait_long "$ALL_ASLEEP" "the pile did not fall asleep again after particle 0 struck it"
}

run_pile sleep_only sleep
read -r all_a vivid_a slate_a amber_a <"$WORK/sleep_only.counts"
echo "Sleep only, pile middle: $all_a pixels, $vivid_a vivid, $slate_a slate, $amber_a amber"
run_pile both sleep contacts
read -r all_b vivid_b slate_b amber_b <"$WORK/both.counts"
echo "Sleep and Contacts, pile middle: $all_b pixels, $vivid_b vivid, $slate_b slate, $amber_b amber"
[ "$all_a" -gt 2000 ] || fail "the pile covers only $all_a pixels"
# Tinted, the sleeping balls are slate; a palette colour survives only in highlights and edges.
[ $((slate_a * 3)) -gt "$all_a" ] || fail "only $slate_a of $all_a pile pixels are in the sleeping tint"
[ $((vivid_a * 10)) -lt "$all_a" ] || fail "$vivid_a of $all_a pile pixels keep a vivid palette colour while asleep"
# The contact lines add amber over the slate pile.
[ "$amber_b" -gt $((amber_a + all_a / 10)) ] || fail "drawing the contacts added no amber lines ($amber_a -> $amber_b pixels)"
echo "OK"
