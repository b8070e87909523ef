#!/usr/bin/env bash
# The generated bash completion offers the commands, each command's own flags, and file names
# after an option that takes a value.
set -euo pipefail
bin=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$bin" --bash-completion > "$tmp/completion.bash"
source "$tmp/completion.bash"
complete_words() {  # complete_words WORD... : completes the last word
    COMP_WORDS=("particle-lab" "$@")
    COMP_CWORD=${#COMP_WORDS[@]}
    COMP_CWORD=$((COMP_CWORD - 1))
    COMPREPLY=()
    _particle_lab
    echo "${COMPREPLY[*]}"
}
[ "$(complete_words ru)" = "run" ] || { echo "command: got '$(complete_words ru)'"; exit 1; }
[ "$(complete_words run --ev)" = "--events --every" ] || { echo "run flags: got '$(complete_words run --ev)'"; exit 1; }
[ "$(complete_words accuracy --cs)" = "--csv" ] || { echo "accuracy flags: got '$(complete_words accuracy --cs)'"; exit 1; }
[ -z "$(complete_words validate --ev)" ] || { echo "validate offered run's flags"; exit 1; }
touch "$tmp/out.csv"
[ "$(complete_words run x.json --out "$tmp/ou")" = "$tmp/out.csv" ] || { echo "--out: no file name offered"; exit 1; }
echo OK
