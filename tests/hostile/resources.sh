# Work the machine cannot do is refused before it starts, with the numbers; absurd step counts
# never slip past the whole-number-of-steps check; messages stay readable.
source "$(dirname "$0")/hostile_lib.bash"

# 2e6 particles x 1000 variants: about 390 GB. It used to die in std::bad_alloc (exit 1).
$gen big 2000000 >"$work/big.json"
expect_exit memory 512 10 2 'needs about [0-9.]+ GB of memory \(2000000 particles x 1000 variants x [0-9]+ bytes\), but the machine has [0-9.]+ GB available' -- \
  "$app" run "$work/big.json"
expect_exit memory_compare 512 10 2 'needs about [0-9.]+ GB of memory' -- "$app" compare "$work/big.json"
# With collisions on, the collision pass holds some 30x the particle state: 2e6 balls x 64
# variants is about 550 GB with it (18 GB without), and the refusal says where it goes.
$gen colliding 2000000 >"$work/colliding.json"
expect_exit memory_collisions 512 10 2 'needs about [0-9.]+ GB of memory \(2000000 particles x 64 variants x [0-9]+ bytes, and [0-9]+ bytes more per particle in the 64 variants with collisions\).*turn collisions off' -- \
  "$app" run "$work/colliding.json"

# Tiny steps and huge durations: refused with the estimate, or with the step count.
$gen dt 1e-12 >"$work/dt_tiny.json"
expect_exit dt_1e-12 256 10 2 'would take at least [0-9.]+ days \(5e\+12 steps x 1 particle x 1 variant\)' -- "$app" run "$work/dt_tiny.json"
$gen dt 5e-324 >"$work/dt_denormal.json"
expect_exit dt_5e-324 256 10 2 'more than can be counted \(2\^53\)' -- "$app" run "$work/dt_denormal.json"
$gen dt 0.001 >"$work/ball.json"
expect_exit duration_1e308 256 10 2 '--duration: 1e\+308 s is inf steps of dt = 0.001 s.*more than can be counted' -- \
  "$app" run "$work/ball.json" --duration 1e308
expect_exit duration_1e10 256 10 2 'would take at least [0-9.e+]+ days' -- "$app" compare "$work/ball.json" --duration 1e10
expect_exit accuracy_dt_1e-300 256 10 2 '--dt: would take at least [0-9.e+]+ years \(2e\+300 steps' -- \
  "$app" accuracy "$work/ball.json" --dt 1e-300

# Messages: no wrapped-around index, no raw terminal escape codes, a physical mass bound.
expect_exit particle_minus_one 256 10 2 "--particle: must be a whole number >= 0, got '-1'" -- \
  "$app" compare "$work/ball.json" --particle -1
$gen name >"$work/name.json"
expect_exit name_escaped_run 256 10 0 'evil\\x1b\[2J\\x1b\]0;pwned\\x07\\x0dname: 1 particle' -- "$app" run "$work/name.json"
expect_exit name_escaped_compare 256 10 0 'evil\\x1b\[2J' -- "$app" compare "$work/name.json"
for out in name_escaped_run name_escaped_compare; do
  if grep -q $'\x1b' "$work/$out.out"; then fail "$out: a raw ESC reached the terminal"; fi
done
sed 's/"position": \[0, 0, 0\]/"position": [0, 0, 0], "mass": 5e-324/' "$work/ball.json" >"$work/light.json"
expect_exit mass_5e-324 256 10 2 'particles\[0\].mass: must be >= 1e-15, got 5e-324' -- "$app" validate "$work/light.json"
finish
