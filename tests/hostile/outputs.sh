# Outputs never lose the user's data: CSV files are written whole or not at all, an output is
# never the input nor the other output, every failed write is an exit 1 with the reason, and no
# event is dropped whatever --every is.
source "$(dirname "$0")/hostile_lib.bash"
preset=$src/presets/default.json

# Events beyond the simulation's pending cap (2^20) between two --every points: ~1.3M events.
$gen events 25000 >"$work/events.json"
expect_exit events_not_dropped 2048 60 0 'events: [0-9]+ bounce' -- \
  "$app" run "$work/events.json" --duration 4 --every 100000000 --events "$work/events.csv"
rows=$(($(wc -l <"$work/events.csv") - 1))
counted=$(grep -Eo 'events: [0-9]+ bounce, [0-9]+ rest, [0-9]+ stop, [0-9]+ lift, [0-9]+ frozen' "$work/events_not_dropped.out" |
  grep -Eo '[0-9]+' | paste -sd+ | bc)
[ "$rows" -gt 1048576 ] || fail "events_not_dropped: only $rows events; the scene must make more than the 2^20 cap"
[ "$rows" -eq "$counted" ] || fail "events_not_dropped: $rows rows in the CSV, the summary counts $counted"

# An output that is the input or the other output is refused; the preset is untouched.
cp "$preset" "$work/p.json"
expect_exit out_is_preset 512 10 2 "--out '.*p.json' is the preset itself" -- "$app" run "$work/p.json" --out "$work/p.json"
cmp -s "$preset" "$work/p.json" || fail "out_is_preset: the preset was changed"
expect_exit events_is_preset 512 10 2 "--events '.*' is the preset itself" -- "$app" run "$work/p.json" --events "$work/./p.json"
expect_exit out_is_events 512 10 2 "--out and --events name the same file" -- \
  "$app" run "$preset" --out "$work/a.csv" --events "$work/../$(basename "$work")/a.csv"

# Failures give the reason; a failed write keeps the old file and leaves no temporary file.
expect_exit cannot_open 512 10 1 "cannot open '/nonexistent/x.csv' for writing: .*No such file or directory" -- \
  "$app" run "$preset" --out /nonexistent/x.csv
expect_exit out_full 512 10 1 "writing '/dev/full' failed: No space left on device" -- "$app" run "$preset" --out /dev/full

# Every command's report to a full standard output is a failure with a message.
for command in "validate $preset" "compare $preset" "run $preset" "advise $preset" "accuracy $preset" \
  "stability --quick" "bench --quick"; do
  # shellcheck disable=SC2086
  expect_exit "stdout_full_${command%% *}" 1024 30 1 "cannot write the standard output" -- \
    bash -c "exec \"\$0\" \"\$@\" >/dev/full" "$app" $command
done

# SIGINT, SIGTERM, SIGHUP mid-run: exit 128 + signal, the old output kept, no temporary file left.
for signal in INT TERM HUP; do
  echo "old contents" >"$work/traj.csv"
  "$app" run "$work/events.json" --duration 60 --out "$work/traj.csv" 2>"$work/signal.err" &
  pid=$!
  sleep 1
  kill -s "$signal" "$pid"
  code=0
  wait "$pid" || code=$?
  want=$((128 + $(kill -l "$signal")))
  [ "$code" -eq "$want" ] || fail "SIG$signal: exit $code, expected $want"
  grep -q "interrupted by SIG$signal" "$work/signal.err" || fail "SIG$signal: no message: $(cat "$work/signal.err")"
  [ "$(cat "$work/traj.csv")" = "old contents" ] || fail "SIG$signal: the old output was changed"
  leftover=$(find "$work" -name 'traj.csv.tmp*' | wc -l)
  [ "$leftover" -eq 0 ] || fail "SIG$signal: $leftover temporary files left"
  echo "ok: SIG$signal (exit $code, old output kept)"
done
finish
