#!/usr/bin/env bash
# Runs a command with a display: the current one, or a fresh Xvfb when none is set.
if [ -n "${DISPLAY:-}" ]; then exec "$@"; fi
exec xvfb-run -a -s "-screen 0 1600x900x24" "$@"
