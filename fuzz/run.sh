#!/usr/bin/env bash
# ./lab fuzz [SECONDS]: builds the preset-loader fuzzer with clang (libFuzzer + AddressSanitizer +
# UndefinedBehaviorSanitizer) into build/fuzz/ and runs it for SECONDS (default 60), seeded with
# the bad-preset catalogue, the shipped presets and fuzz/hostile_corpus (huge, deep inputs).
# Crashing inputs are kept in build/fuzz/.
set -euo pipefail
cd "$(dirname "$(readlink -f "$0")")/.."

seconds=${1:-60}
if ! [[ $seconds =~ ^[0-9]+$ ]] || [ "$seconds" -eq 0 ]; then
  echo "usage: ./lab fuzz [SECONDS]   (SECONDS: a whole number > 0, default 60)" >&2
  exit 2
fi

# clang and its runtime libraries (libFuzzer, sanitizers) are only needed here, so they are
# installed on demand rather than by ./lab run/test.
packages=(clang libclang-rt-14-dev nlohmann-json3-dev libfmt-dev libglm-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "fuzz: installing Debian packages: ${missing[*]}" >&2
  sudo=()
  [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

out=build/fuzz
binary=$out/preset_fuzzer
# The loader and what it links against; nothing else of physics/ is needed.
sources=(fuzz/preset_fuzzer.cpp io/preset_io.cpp io/atomic_output.cpp io/preset_parse.cpp io/preset_reader.cpp io/preset_paths.cpp io/value_reader.cpp io/preset_writer.cpp physics/model/scene.cpp physics/model/emitter.cpp physics/model/start_packing.cpp physics/model/sphere_overlaps.cpp)
mkdir -p "$out"
# The same include roots as the CMake targets: only physics/ and io/ are visible.
mkdir -p "$out/include"
ln -sfn "$PWD/physics" "$out/include/physics"
ln -sfn "$PWD/io" "$out/include/io"
if [ ! -x "$binary" ] || [ -n "$(find "${sources[@]}" physics io -name '*.hpp' -newer "$binary" 2>/dev/null | head -1)" ]; then
  echo "fuzz: building $binary" >&2
  clang++ -std=c++20 -O1 -g -fno-omit-frame-pointer \
    -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all \
    -Wall -Wextra -Wpedantic -I"$out/include" "${sources[@]}" -lfmt -o "$binary"
fi

# libFuzzer adds what it finds to its first corpus directory: use a temporary one, so the
# catalogue in tests/ is only ever read.
corpus=$(mktemp -d "${TMPDIR:-/tmp}/pl_fuzz_corpus.XXXXXX")
trap 'rm -rf "$corpus"' EXIT
cp tests/bad_presets/*.json presets/*.json fuzz/hostile_corpus/*.json "$corpus"/
# libFuzzer takes one dictionary: the format's tokens plus the structure-aware hostile entries.
cat fuzz/preset.dict fuzz/hostile.dict >"$corpus.dict"
trap 'rm -rf "$corpus" "$corpus.dict"' EXIT

echo "fuzz: running for $seconds s on $(ls "$corpus" | wc -l) seed inputs" >&2
"$binary" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=16384 \
  -dict="$corpus.dict" -artifact_prefix="$out/" -print_final_stats=1 "$corpus"
