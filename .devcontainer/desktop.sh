#!/usr/bin/env bash
# The dev container's browser desktop: an X display :1 (Xvfb, 1280x800), fluxbox, a VNC server on it and
# noVNC on port 6080. Open http://localhost:6080/vnc.html, then run ./lab gui in the container's
# terminal: the app's window appears in the browser. Started by devcontainer.json (postStartCommand);
# running it again does nothing when the desktop is up.
set -u
if pgrep -x websockify >/dev/null; then echo "desktop: already running on port 6080"; exit 0; fi
log=${TMPDIR:-/tmp}/clothlab-desktop.log
: >"$log"
Xvfb :1 -screen 0 1280x800x24 >>"$log" 2>&1 &
for _ in $(seq 50); do [[ -e /tmp/.X11-unix/X1 ]] && break; sleep 0.1; done
DISPLAY=:1 fluxbox >>"$log" 2>&1 &
x11vnc -display :1 -forever -shared -nopw -localhost -rfbport 5900 -quiet >>"$log" 2>&1 &
websockify --web /usr/share/novnc 6080 localhost:5900 >>"$log" 2>&1 &
echo "desktop: open http://localhost:6080/vnc.html (log: $log)"
