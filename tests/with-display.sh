#!/usr/bin/env bash
# Runs a test that needs a display server: as it is where DISPLAY is set, else under Xvfb
# (docs/architecture.md, "OpenGL without a display": Qt's offscreen platform cannot give a usable GL context here).
if [ -n "${DISPLAY:-}" ]; then exec "$@"; fi
exec xvfb-run -a -s "-screen 0 1280x1024x24" "$@"
