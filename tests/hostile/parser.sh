# Hostile presets that are huge or deep rather than wrong: the loader stays linear in time and
# memory, and says what limit was hit.
source "$(dirname "$0")/hostile_lib.bash"

# 4 MB of nesting: before the limit, 80 KB took 2.4 GB and 2 MB ran the machine out of memory.
$gen deep 2000000 >"$work/deep.json"
expect_exit deep 256 10 2 'description(\[0\])+: objects and arrays nested more than 32 levels deep' -- \
  "$app" validate "$work/deep.json"

# 200k unknown keys (2.7 MB): 39 s before the key index, now well under a second.
$gen keys 200000 >"$work/keys.json"
expect_exit unknown_keys 512 8 2 'and 199000 more errors not shown' -- \
  "$app" validate "$work/keys.json"

# 100 numbers too large for a double after a 16 MB string: each used to re-parse the whole text.
$gen overflow 16000000 >"$work/overflow.json"
expect_exit overflows 512 8 2 'world.o99: must be finite, but the number 1e400 is too large for a double' -- \
  "$app" validate "$work/overflow.json"

# The file-size limit names itself and the flag that lifts it.
$gen dt 0.001 >"$work/small.json"
expect_exit size_limit 256 5 2 "is too large \([0-9]+ bytes; the preset size limit is 100 bytes\); raise it with --max-preset-bytes" -- \
  "$app" validate --max-preset-bytes 100 "$work/small.json"
expect_exit size_limit_lifted 256 5 0 '^ok: 1 particle' -- "$app" validate --max-preset-bytes 100000 "$work/small.json"
finish
