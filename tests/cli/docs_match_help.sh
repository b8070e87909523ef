#!/usr/bin/env bash
# docs/cli.md is what `particle-lab --markdown-help` generates from the option definitions, and
# the README's "Command line" section names every command and every flag that --help lists.
set -euo pipefail
bin=$1 src=$2
"$bin" --markdown-help | diff -u "$src/docs/cli.md" - ||
    { echo "docs/cli.md is stale: regenerate it with 'particle-lab --markdown-help > docs/cli.md'"; exit 1; }
section=$(sed -n '/^## Command line/,/^## /p' "$src/README.md")
commands=$("$bin" --help | sed -n '/^Subcommands:/,/^$/p' | awk 'NF && !/^Subcommands:/ {print $1}')
[ -n "$commands" ] || { echo "no commands in --help"; exit 1; }
missing=""
for c in $commands; do
    grep -q "particle-lab $c" <<<"$section" || missing+=" $c"
    for flag in $("$bin" "$c" --help | grep -oE '^  (-[a-z],)?--[a-z0-9-]+' | sed 's/.*--/--/'); do
        [ "$flag" = --help ] || grep -qF -- "$flag" <<<"$section" || missing+=" $c$flag"
    done
done
[ -z "$missing" ] || { echo "README's Command line section does not mention:$missing"; exit 1; }
echo OK
