#!/usr/bin/env python3
"""Runs pages in headless chromium and prints each page's clothlab status (window.clothlab) as JSON.

    page_run.py URL... [--serve DIR] [--seconds S] [--until-done] [--screenshot FILE.png] [--mouse]
                [--controls --downloads DIR]

Chromium is driven over its DevTools protocol on a pipe (--remote-debugging-pipe: file descriptors 3
and 4, messages ending in NUL), so only the standard library is needed. It loads each URL in turn in
one browser, polls window.clothlab every 0.25 s for S seconds of wall time (default 10), or until its
`done` is true (or the page or a run shows a message: stopped) with --until-done, saves a screenshot and prints the last status, one JSON line per
URL, with `console_errors`: every console.error, uncaught exception and error logged by the browser
(network errors included) while that URL ran. With several URLs the screenshots are FILE-0.png,
FILE-1.png, ... With --serve DIR the URLs are paths served from DIR (python3's http.server on a free
port of 127.0.0.1), e.g. "index.html?scene=spring".
--mouse (after the page is done): the mouse as a user drives it, through the page's `probe` (the first
run's middle particle and where it is drawn, framework/app/web_main.cpp): the left button pressed on
it and dragged 120 CSS pixels up, released, then a right click on it (the pin toggle); the status gets
`mouse`: the probe and the pinned count before, during the drag, after the release and after the
right click (Input.dispatchMouseEvent: real DOM events on the canvas).
--controls (after the page has played S seconds): the panel's buttons and keys as a user presses them,
clicked where the status says the panel drew them (app.controls): Pause, a second of nothing, Step, the
keys S and space (twice), Reset, the method combo and its "xpbd", Play, "Save PNG", "Export CSV + PNG"
and "+ compare";
the status gets `controls`: playing, step, t, the method, finite, message after each, and the downloads
(window.clothlab_downloads and the files chromium saved into --downloads DIR).
Chromium renders with SwiftShader (no GPU): --use-angle=swiftshader --enable-unsafe-swiftshader.
"""
import argparse, base64, json, os, subprocess, sys, tempfile, time

ap = argparse.ArgumentParser()
ap.add_argument("urls", nargs="+")
ap.add_argument("--serve")
ap.add_argument("--seconds", type=float, default=10.0)
ap.add_argument("--until-done", action="store_true")
ap.add_argument("--screenshot")
ap.add_argument("--mouse", action="store_true")
ap.add_argument("--controls", action="store_true")
ap.add_argument("--downloads")
args = ap.parse_args()

server = None
if args.serve:
    import socket
    sock = socket.socket()
    sock.bind(("127.0.0.1", 0))
    port = sock.getsockname()[1]
    sock.close()
    server = subprocess.Popen([sys.executable, "-m", "http.server", str(port), "--bind", "127.0.0.1", "--directory", args.serve],
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    import urllib.request
    for _ in range(100):
        try:
            urllib.request.urlopen("http://127.0.0.1:%d/" % port)
            break
        except Exception:
            time.sleep(0.1)
    args.urls = ["http://127.0.0.1:%d/%s" % (port, u.lstrip("/")) for u in args.urls]

to_chrome_r, to_chrome_w = os.pipe()
from_chrome_r, from_chrome_w = os.pipe()
profile = tempfile.mkdtemp(prefix="clothlab-chromium-")


def child_fds():
    os.dup2(to_chrome_r, 3)
    os.dup2(from_chrome_w, 4)


chrome = subprocess.Popen(
    ["chromium", "--headless", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
     "--remote-debugging-pipe", "--user-data-dir=" + profile, "--window-size=1280,800", "about:blank"],
    pass_fds=(3, 4, to_chrome_r, from_chrome_w), preexec_fn=child_fds, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
os.close(to_chrome_r)
os.close(from_chrome_w)
buf = b""
next_id = 0
errors = []


def handle(msg):
    m, p = msg.get("method"), msg.get("params", {})
    if m == "Runtime.consoleAPICalled" and p.get("type") in ("error", "assert"):
        errors.append("console.error: " + " ".join(str(a.get("value", a.get("description", ""))) for a in p.get("args", [])))
    elif m == "Runtime.exceptionThrown":
        d = p.get("exceptionDetails", {})
        errors.append("exception: " + d.get("exception", {}).get("description", d.get("text", "")))
    elif m == "Log.entryAdded" and p.get("entry", {}).get("level") == "error":
        e = p["entry"]
        errors.append("browser (%s): %s %s" % (e.get("source"), e.get("text"), e.get("url", "")))


def call(method, params=None, session=None, timeout=60):
    global next_id, buf
    next_id += 1
    msg = {"id": next_id, "method": method, "params": params or {}}
    if session:
        msg["sessionId"] = session
    os.write(to_chrome_w, json.dumps(msg).encode() + b"\0")
    deadline = time.time() + timeout
    while time.time() < deadline:
        while b"\0" in buf:
            raw, buf = buf.split(b"\0", 1)
            reply = json.loads(raw)
            if reply.get("id") == next_id:
                if "error" in reply:
                    raise RuntimeError("%s: %s" % (method, reply["error"]))
                return reply.get("result", {})
            handle(reply)
        chunk = os.read(from_chrome_r, 1 << 20)
        if not chunk:
            raise RuntimeError("chromium closed the pipe")
        buf += chunk
    raise RuntimeError(method + ": no answer in %d s" % timeout)


def read_status(s):
    r = call("Runtime.evaluate", {"expression": "JSON.stringify(window.clothlab || null)", "returnByValue": True}, session=s)
    v = r.get("result", {}).get("value")
    return json.loads(v) if v and v != "null" else None


def mouse(s, kind, x, y, button="none", buttons=0):
    call("Input.dispatchMouseEvent", {"type": kind, "x": x, "y": y, "button": button, "buttons": buttons,
                                      "clickCount": 1 if kind != "mouseMoved" else 0}, session=s)
    time.sleep(0.3)  # a few frames: the app reads the events in its next frame


def probe_of(st):
    st = st or {}
    return {"probe": st.get("probe"), "pinned": st.get("pinned"), "finite": st.get("finite"), "message": st.get("message")}


def drive_mouse(s, status):
    out = {"before": probe_of(status)}
    p = (status.get("probe") or {}).get("px")
    if not p or p[0] is None:
        out["error"] = "no probe in the status"
        return out
    x, y = p
    mouse(s, "mouseMoved", x, y)
    mouse(s, "mousePressed", x, y, "left", 1)
    for k in range(1, 7):
        mouse(s, "mouseMoved", x, y - 20 * k, "left", 1)
    time.sleep(0.5)
    out["during"] = probe_of(read_status(s))
    mouse(s, "mouseReleased", x, y - 120, "left", 0)
    time.sleep(0.5)
    after = read_status(s)
    out["after"] = probe_of(after)
    q = ((after or {}).get("probe") or {}).get("px") or p
    mouse(s, "mouseMoved", q[0], q[1])
    mouse(s, "mousePressed", q[0], q[1], "right", 2)
    mouse(s, "mouseReleased", q[0], q[1], "right", 0)
    time.sleep(0.5)
    out["pin"] = probe_of(read_status(s))
    return out


def key(s, text, code, vk):
    for kind in ("keyDown", "keyUp"):
        call("Input.dispatchKeyEvent", {"type": kind, "key": text, "code": code, "windowsVirtualKeyCode": vk,
                                        "text": text if kind == "keyDown" else ""}, session=s)
    time.sleep(0.4)


def controls_of(st):
    app = (st or {}).get("app") or {}
    runs = app.get("runs") or [{}]
    return {"playing": app.get("playing"), "step": (st or {}).get("step"), "t": (st or {}).get("t"),
            "method": runs[0].get("method"), "finite": (st or {}).get("finite"), "message": (st or {}).get("message"),
            "runs": [{"steps": r.get("steps"), "label": r.get("label_text")} for r in runs]}


def click(s, name):
    """Clicks the panel's control NAME where the last status says it was drawn; False when it is not there."""
    r = (((read_status(s) or {}).get("app") or {}).get("controls") or {}).get(name)
    if not r:
        return False
    x, y = r[0] + r[2] / 2, r[1] + r[3] / 2
    mouse(s, "mouseMoved", x, y)
    mouse(s, "mousePressed", x, y, "left", 1)
    mouse(s, "mouseReleased", x, y, "left", 0)
    return True


def drive_controls(s, status):
    out = {"playing": controls_of(status), "missing": []}

    def press(name, wait=0.5):
        if not click(s, name):
            out["missing"].append(name)
        time.sleep(wait)
        return controls_of(read_status(s))

    out["paused"] = press("play")
    time.sleep(1.0)
    out["paused_later"] = controls_of(read_status(s))
    out["stepped"] = press("step")
    key(s, "s", "KeyS", 83)
    out["key_s"] = controls_of(read_status(s))
    key(s, " ", "Space", 32)
    time.sleep(1.0)
    out["key_space"] = controls_of(read_status(s))
    key(s, " ", "Space", 32)
    out["key_space_again"] = controls_of(read_status(s))
    out["reset"] = press("reset")
    press("method")
    out["method"] = press("method=xpbd")
    out["method_plays"] = press("play", 1.5)
    press("save_png", 1.0)
    press("export", 1.0)
    out["side_by_side"] = press("compare", 2.0)
    r = call("Runtime.evaluate", {"expression": "JSON.stringify(window.clothlab_downloads || [])", "returnByValue": True}, session=s)
    out["downloads"] = json.loads(r.get("result", {}).get("value") or "[]")
    if args.downloads:
        time.sleep(1.0)
        out["saved"] = sorted(f for f in os.listdir(args.downloads) if not f.endswith(".crdownload"))
    return out


results = []
try:
    target = call("Target.createTarget", {"url": "about:blank"})["targetId"]
    s = call("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
    call("Runtime.enable", session=s)
    call("Log.enable", session=s)
    call("Page.enable", session=s)
    if args.downloads:
        call("Browser.setDownloadBehavior", {"behavior": "allow", "downloadPath": os.path.abspath(args.downloads)})
    for i, url in enumerate(args.urls):
        errors = []
        status = {}
        call("Page.navigate", {"url": url}, session=s)
        end = time.time() + args.seconds
        while time.time() < end:
            time.sleep(0.25)
            status = read_status(s) or status
            stopped = status.get("message") or any(r.get("message") for r in (status.get("app") or {}).get("runs", []))
            if args.until_done and (status.get("done") or stopped):
                break
        if args.mouse:
            status["mouse"] = drive_mouse(s, status)
            status.update({k: v for k, v in (read_status(s) or {}).items() if k not in ("mouse",)})
        if args.controls:
            status["controls"] = drive_controls(s, status)
            status.update({k: v for k, v in (read_status(s) or {}).items() if k not in ("controls",)})
        if args.screenshot:
            shot = args.screenshot if len(args.urls) == 1 else args.screenshot[:-4] + "-%d.png" % i
            png = call("Page.captureScreenshot", {"format": "png"}, session=s)["data"]
            with open(shot, "wb") as f:
                f.write(base64.b64decode(png))
        # The same status as the page mirrors into #clothlab-status (what --dump-dom would read).
        r = call("Runtime.evaluate", {"expression": "(document.getElementById('clothlab-status') || {}).textContent || ''",
                                      "returnByValue": True}, session=s)
        status["element_mirrors_status"] = bool(r.get("result", {}).get("value"))
        status["url"] = url
        status["console_errors"] = status.get("console_errors", []) + errors
        results.append(status)
        json.dump(status, sys.stdout)
        print(flush=True)
finally:
    try:
        call("Browser.close", timeout=5)
    except Exception:
        pass
    chrome.wait(timeout=30)
    subprocess.run(["rm", "-rf", profile])
    if server:
        server.kill()
